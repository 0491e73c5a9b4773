#include "ballsight/eval/omni_experiment.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <set>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/model_ground_map.hpp"
#include "ballsight/calib/omni_model_fit.hpp"
#include "ballsight/calib/simulated_calibration.hpp"
#include "ballsight/camera/iris_lut.hpp"
#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/eval/wall_clock.hpp"
#include "ballsight/pipeline/marker_frame_samples.hpp"
#include "ballsight/pipeline/omni_pipelines.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_scenario.hpp"

namespace ballsight {

void OmniExperimentOptions::validate() const {
  const std::string where = "eval omni";
  require(std::isfinite(click_noise_px) && click_noise_px >= 0.0 && click_noise_px <= 10.0, where,
          "click_noise_px must be in [0, 10]");
  require(!distances_cm.empty(), where, "needs at least one robot distance");
  for (int d : distances_cm) require(d >= 60 && d <= 460, where, "distances must be 60..460 cm");
  require(turn_step_deg >= 1.0 && turn_step_deg <= 180.0, where, "turn_step_deg must be 1..180");
  require(!methods.empty(), where, "needs at least one method");
  require(!measured_height_sigma_cm ||
              (std::isfinite(*measured_height_sigma_cm) && *measured_height_sigma_cm > 0.0),
          where, "measured_height_sigma_cm must be a positive number");
  for (const std::string& m : methods) {
    if (m != "oracle" && m != "ballsight-auto") parse_omni_method(m, where + " method");
  }
  rig_params().validate();
}

OmniRigParams OmniExperimentOptions::rig_params() const {
  OmniRigParams rig;
  rig.tilt_deg = tilt_deg;
  rig.tilt_azimuth_deg = tilt_azimuth_deg;
  rig.center_offset_px = center_offset_px;
  return with_mirror(rig, mirror);
}

namespace {

using Clock = std::chrono::steady_clock;

using Locate = std::function<std::optional<Vec2>(const cv::Mat&, const Pose2D&)>;

double sample_std(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double sum = 0.0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(v.size() - 1));
}

DistanceResult summarise(std::vector<std::optional<Vec2>> estimates, const Vec2& truth) {
  DistanceResult r;
  std::vector<double> xs, ys;
  double error_sum = 0.0;
  for (const auto& e : estimates) {
    if (!e) continue;
    ++r.found;
    error_sum += (*e - truth).norm();
    xs.push_back(e->x());
    ys.push_back(e->y());
  }
  r.mean_error_cm = r.found ? error_sum / r.found : std::nan("");
  r.std_x_cm = sample_std(xs);
  r.std_y_cm = sample_std(ys);
  r.estimates_cm = std::move(estimates);
  return r;
}

// One robot pose per distance and heading: the robot south of the ball, turned so that the ball
// is at `angle` to its heading (the paper's "robot angle to ball").
Pose2D robot_pose_m(const OmniExperimentOptions& o, int distance_cm, double angle_deg) {
  const Vec2 position = (o.ball_cm - Vec2(0.0, distance_cm)) / 100.0;
  return {position, rad_from_deg(90.0 - angle_deg)};
}

// The paper's run-time pipeline (Algorithms 3-6) over a distance function.
Locate paper_locate(const YuvRange& ball_color, const Vec2& center_px, RadialDistanceFn distance) {
  auto pipeline =
      std::make_shared<const PaperOmniPipeline>(ball_color, center_px, std::move(distance));
  return [pipeline](const cv::Mat& f, const Pose2D& p) { return pipeline->locate_cm(f, p); };
}

// ballsight's run-time pipeline over a ground map, which it keeps alive.
Locate ballsight_locate(const YuvRange& ball_color, GroundMap map) {
  auto owned = std::make_shared<const GroundMap>(std::move(map));
  auto pipeline = std::make_shared<const BallsightOmniPipeline>(ball_color, *owned, BallOnFloor{});
  return [owned, pipeline](const cv::Mat& f, const Pose2D& p) { return pipeline->locate_cm(f, p); };
}

// ballsight's own calibration, without clicking: the markers of one rendered calibration frame
// found, matched and their centroid shifts removed (pipeline/marker_frame_samples.hpp).
std::vector<PolarSample> auto_calibration_samples(const OmniRigParams& rig,
                                                  const OmniExperimentOptions& options,
                                                  const Vec2& configured_center) {
  sim::OmniScene scene;
  scene.rig = rig;
  scene.robot_pose = {{4.0, 6.0}, 0.0};
  scene.markers = sim::calibration_markers(scene.robot_pose);
  scene.effects.noise_sigma = options.sensor_noise;
  scene.noise_seed = options.seed * 1000 + 999;  // the test frames use seed * 1000 + 0..35
  const std::vector<LayoutMarker> layout = layout_markers();
  return samples_from_marker_frame(sim::render_omni_scene(scene).bgr, layout,
                                   scene.palette.marker_bgr, configured_center)
      .samples;
}

Pose2D in_cm(const Pose2D& pose_m) {
  return {pose_m.position * 100.0, pose_m.heading_rad};
}

}  // namespace

OmniExperimentResult run_omni_experiment(const OmniExperimentOptions& options) {
  options.validate();
  const OmniRigParams rig_params = options.rig_params();
  const OmniRig rig(rig_params);
  // The robot is configured with the nominal image centre; the mirror's is off by the offset.
  const Vec2 configured_center(0.5 * (rig_params.width - 1), 0.5 * (rig_params.height - 1));

  // Calibration (Section III-A): markers 60-460 cm every 10 deg, clicked with noise around the
  // configured image centre. Every method gets the same samples.
  SimulatedCalibrationOptions calibration;
  calibration.click_noise_px = options.click_noise_px;
  calibration.assumed_center_px = configured_center;
  calibration.seed = options.seed;
  const SimulatedCalibration clicks = simulate_calibration(rig, calibration);
  const OmniImage image{rig_params.width, rig_params.height, configured_center};
  const std::vector<FloorTruth> held_out =
      random_floor_truth(rig, 60.0, 460.0, 2000, options.seed + 1);

  OmniExperimentResult result;
  result.options = options;
  const std::set<std::string> selected(options.methods.begin(), options.methods.end());
  std::map<std::string, Locate> pipelines;
  // The run-time pipelines. The paper's robots read the MLP through its Eq. 7-8 table and
  // evaluate the polynomial directly (its Table VI "old calibration").
  const YuvRange ball_color = yuv_range_around(sim::OmniPalette{}.ball_bgr);
  OmniFitOptions fit_options;
  if (options.measured_height_sigma_cm) {
    std::mt19937_64 rng(options.seed + 2);
    const double sigma = *options.measured_height_sigma_cm;
    fit_options.ballsight.viewpoint_height_cm =
        100.0 * rig.viewpoint_height_m() + sigma * std::normal_distribution<double>()(rng);
    fit_options.ballsight.viewpoint_height_sigma_cm = sigma;
  }
  const auto record_fit = [&](const std::string& name, Clock::time_point start,
                              const OmniGroundModel& model) {
    OmniMethodResult& fitted = result.methods[name];
    fitted.fit_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    fitted.held_out_median_cm = ground_errors(model, held_out).position_cm.median;
  };
  for (OmniMethod method : {OmniMethod::kPoly, OmniMethod::kPaperMlp, OmniMethod::kBallsight}) {
    const std::string name(omni_method_name(method));
    if (!selected.contains(name)) continue;
    const auto start = Clock::now();
    std::shared_ptr<const OmniGroundModel> model =
        fit_omni_model(method, clicks.samples, image, fit_options);
    record_fit(name, start, *model);
    switch (method) {
      case OmniMethod::kPoly:  // Algorithm 1, evaluated directly
        pipelines[name] = paper_locate(ball_color, configured_center,
                                       [model](double theta, double r) -> std::optional<double> {
                                         const double d = model->predict(theta, r).distance_cm;
                                         return std::isfinite(d) ? std::optional(d) : std::nullopt;
                                       });
        break;
      case OmniMethod::kPaperMlp: {
        auto table = std::make_shared<const IrisLut>(
            build_iris_px2cm([&](double theta, double r) -> std::optional<double> {
              const double d = model->predict(theta, r).distance_cm;
              return std::isfinite(d) ? std::optional(d) : std::nullopt;
            }));
        pipelines[name] = paper_locate(ball_color, configured_center,
                                       [table](double theta, double r) -> std::optional<double> {
                                         const auto d = iris_distance_cm(*table, theta, r);
                                         if (!d || *d <= 0) return std::nullopt;
                                         return static_cast<double>(*d);
                                       });
        break;
      }
      case OmniMethod::kBallsight:
        pipelines[name] = ballsight_locate(ball_color, ground_map_from_model(*model));
        break;
    }
  }
  if (selected.contains("ballsight-auto")) {
    const auto start = Clock::now();
    try {
      const BallsightGroundModel model =
          fit_ballsight_model(auto_calibration_samples(rig_params, options, configured_center),
                              image, fit_options.ballsight);
      record_fit("ballsight-auto", start, model);
      pipelines["ballsight-auto"] = ballsight_locate(ball_color, ground_map_from_model(model));
    } catch (const InputError& e) {
      // The markers of this rig's frame could not be found or matched: reported, not fatal.
      result.methods["ballsight-auto"].calibration_error = e.what();
    }
  }
  if (selected.contains("oracle")) {
    // The true mapping over the range the markers cover, through ballsight's detector.
    const RadiusRange range = valid_radius_from_samples(clicks.samples);
    GroundMapInfo info;
    info.width = image.width;
    info.height = image.height;
    info.image_center_px = image.center_px;
    info.min_radius_px = range.min_px;
    info.max_radius_px = range.max_px;
    info.method = "oracle";
    pipelines["oracle"] = ballsight_locate(ball_color, ground_map_from_rig(rig, info));
  }

  // The test (Section V-A): render each pose once, every method sees the same frame.
  const sim::OmniRenderer renderer(rig_params);
  std::map<std::string, std::map<int, std::vector<std::optional<Vec2>>>> estimates;
  std::uint64_t frame = 0;
  for (int distance : options.distances_cm) {
    for (double angle = 0.0; angle < 360.0 - 1e-9; angle += options.turn_step_deg) {
      sim::OmniScene scene;
      scene.rig = rig_params;
      scene.robot_pose = robot_pose_m(options, distance, angle);
      scene.ball = sim::OmniBall{options.ball_cm / 100.0};
      scene.effects.noise_sigma = options.sensor_noise;
      scene.noise_seed = options.seed * 1000 + frame++;
      const cv::Mat bgr = renderer.render(scene).bgr;
      for (const auto& [name, locate] : pipelines)
        estimates[name][distance].push_back(locate(bgr, in_cm(scene.robot_pose)));
    }
  }
  for (auto& [name, by_distance] : estimates) {
    for (auto& [distance, list] : by_distance)
      result.methods[name].by_distance[distance] = summarise(std::move(list), options.ball_cm);
  }
  return result;
}

nlohmann::json omni_experiment_json(const OmniExperimentResult& result) {
  nlohmann::json methods = nlohmann::json::object();
  for (const auto& [name, method] : result.methods) {
    nlohmann::json by_distance = nlohmann::json::object();
    for (const auto& [distance, r] : method.by_distance) {
      nlohmann::json estimates = nlohmann::json::array();
      for (const auto& e : r.estimates_cm)
        estimates.push_back(e ? nlohmann::json::array({e->x(), e->y()}) : nlohmann::json());
      by_distance[std::to_string(distance)] = {{"mean_error_cm", r.mean_error_cm},
                                               {"std_x_cm", r.std_x_cm},
                                               {"std_y_cm", r.std_y_cm},
                                               {"found", r.found},
                                               {"estimates_cm", estimates}};
    }
    methods[name] = {{"by_distance", by_distance},
                     {"held_out_median_cm", method.held_out_median_cm},
                     {"fit_seconds", method.fit_seconds}};
    if (!method.calibration_error.empty()) {
      methods[name]["calibration_error"] = method.calibration_error;
    }
  }
  const OmniExperimentOptions& o = result.options;
  nlohmann::json out = {{"methods", methods},
                        {"setup",
                         {{"seed", o.seed},
                          {"mirror", mirror_kind_name(o.mirror)},
                          {"tilt_deg", o.tilt_deg},
                          {"tilt_azimuth_deg", o.tilt_azimuth_deg},
                          {"center_offset_px", {o.center_offset_px.x(), o.center_offset_px.y()}},
                          {"sensor_noise", o.sensor_noise},
                          {"click_noise_px", o.click_noise_px},
                          {"ball_cm", {o.ball_cm.x(), o.ball_cm.y()}},
                          {"turn_step_deg", o.turn_step_deg},
                          {"measured_height_sigma_cm",
                           o.measured_height_sigma_cm ? nlohmann::json(*o.measured_height_sigma_cm)
                                                      : nlohmann::json()}}}};
  return with_wall_clock_apart(std::move(out), {"fit_seconds"});
}

std::string omni_experiment_table(const OmniExperimentResult& result) {
  std::string out =
      "method          distance  found  mean error  std x  std y  (cm)   held-out median  fit\n";
  char line[160];
  for (const auto& [name, method] : result.methods) {
    if (!method.calibration_error.empty()) {
      out += name + ": not calibrated: " + method.calibration_error + "\n";
    }
    for (const auto& [distance, r] : method.by_distance) {
      std::snprintf(line, sizeof line, "%-14s %6d cm  %2d/%-2zu %9.2f %7.2f %6.2f %17.2f %6.2f s\n",
                    name.c_str(), distance, r.found, r.estimates_cm.size(), r.mean_error_cm,
                    r.std_x_cm, r.std_y_cm, method.held_out_median_cm, method.fit_seconds);
      out += line;
    }
  }
  return out;
}

}  // namespace ballsight
