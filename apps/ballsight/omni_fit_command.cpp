// `ballsight omni fit` and `ballsight omni predict`: fit a pixel -> ground model to polar
// calibration samples, and apply a fitted model to samples.

#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/ground_map_model.hpp"
#include "ballsight/calib/model_json.hpp"
#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/calib/prediction_csv.hpp"
#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/pipeline/omni_calibration.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

struct FitArgs {
  std::string samples;
  std::string method = "ballsight";
  std::string out;
  std::optional<std::string> center;
  std::optional<std::string> image_size;
  std::optional<int> degree;
  std::optional<double> height_cm;
  std::optional<double> height_sigma_cm;
  std::optional<std::string> model;
};

struct PredictArgs {
  std::optional<std::string> lut;
  std::optional<std::string> model;
  std::string samples;
  std::string out;
};

void run_fit(const FitArgs& args) {
  const OmniMethod method = parse_omni_method(args.method, "--method");
  const std::vector<PolarSample> samples = read_polar_samples_csv(args.samples);
  OmniFitOptions options;
  if (args.degree) {
    require(method == OmniMethod::kPoly, "--degree", "applies only to --method poly");
    options.poly.degree = *args.degree;
  }
  if (args.height_cm) {
    require(method == OmniMethod::kBallsight, "--viewpoint-height-cm",
            "applies only to --method ballsight");
    options.ballsight.viewpoint_height_cm = *args.height_cm;
  }
  if (args.height_sigma_cm) {
    require(args.height_cm.has_value(), "--viewpoint-height-sigma-cm",
            "needs --viewpoint-height-cm");
    options.ballsight.viewpoint_height_sigma_cm = *args.height_sigma_cm;
  }
  std::optional<Vec2> center;
  if (args.center) center = parse_pixel_pair(*args.center, "--center");
  std::optional<Eigen::Vector2i> size;
  if (args.image_size) size = parse_image_size(*args.image_size, "--image-size");
  const OmniImage image = omni_image_for_samples(samples, center, size);
  const OmniCalibration fit = calibrate_omni(method, samples, image, options);
  const OmniGroundModel* model = fit.model.get();
  save_ground_map(args.out, fit.table);
  if (args.model) save_omni_model(*args.model, *model);

  const GroundErrors& errors = fit.errors;
  std::cout << std::fixed << std::setprecision(1) << model->name() << " model from "
            << samples.size() << " samples, image " << image.width << "x" << image.height
            << " centre (" << image.center_px.x() << ", " << image.center_px.y()
            << "), valid radius " << model->domain().valid_radius.min_px << " .. "
            << model->domain().valid_radius.max_px << " px; distance error on the samples: median "
            << errors.distance_cm.median << " cm, p95 " << errors.distance_cm.p95 << " cm -> "
            << args.out << (args.model ? ", " + *args.model : std::string()) << "\n";
}

void run_predict(const PredictArgs& args) {
  require(args.lut.has_value() != args.model.has_value(), "omni predict",
          "give exactly one of --lut FILE and --model FILE");
  const std::unique_ptr<OmniGroundModel> model =
      args.lut ? std::make_unique<GroundMapModel>(load_ground_map(*args.lut))
               : load_omni_model(*args.model);
  const std::vector<PolarSample> samples = read_polar_samples_csv(args.samples);
  write_file_atomic(args.out, format_prediction_csv(*model, samples));
}

}  // namespace

void add_omni_fit_commands(CLI::App& omni) {
  auto fit_args = std::make_shared<FitArgs>();
  CLI::App* fit = omni.add_subcommand(
      "fit",
      "Fit a pixel -> ground model to polar calibration samples (theta_deg, radius_px, "
      "distance_cm[, bearing_deg])");
  fit->add_option("--samples", fit_args->samples, "Samples CSV")->required();
  fit->add_option("--method", fit_args->method,
                  "poly (the paper's polynomial), paper-mlp (the paper's network) or ballsight")
      ->capture_default_str();
  fit->add_option("--out", fit_args->out,
                  "Lookup table to write (ballsight ground map, docs/lut-format.md)")
      ->required();
  fit->add_option("--center", fit_args->center,
                  "Image centre CX,CY the samples' polar coordinates are around (default: the "
                  "image's centre)");
  fit->add_option("--image-size", fit_args->image_size,
                  "Image size WxH (default: one that covers the samples' radii with margin)");
  fit->add_option("--degree", fit_args->degree, "Polynomial degree for --method poly (default 6)");
  fit->add_option("--viewpoint-height-cm", fit_args->height_cm,
                  "For --method ballsight: the mirror's effective viewpoint height above the floor "
                  "as measured on the robot (floor markers determine it poorly)");
  fit->add_option("--viewpoint-height-sigma-cm", fit_args->height_sigma_cm,
                  "Standard deviation of that measurement (default 0.5)");
  fit->add_option("--model", fit_args->model,
                  "Also write the fitted model's parameters (JSON, for omni predict --model)");
  fit->callback([fit_args] { run_fit(*fit_args); });

  auto predict_args = std::make_shared<PredictArgs>();
  CLI::App* predict = omni.add_subcommand(
      "predict",
      "Apply a lookup table (or a fitted model) to samples: copies the rows and adds "
      "predicted_distance_cm, predicted_bearing_deg and in_range");
  predict->add_option("--lut", predict_args->lut, "Lookup table (from omni fit --out)");
  predict->add_option("--model", predict_args->model, "Model file (from omni fit --model)");
  predict->add_option("--samples", predict_args->samples, "Samples CSV")->required();
  predict->add_option("--out", predict_args->out, "Output CSV")->required();
  predict->callback([predict_args] { run_predict(*predict_args); });
}

}  // namespace ballsight::app
