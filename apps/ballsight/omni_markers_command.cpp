// `ballsight omni markers`: calibration without clicking. The floor markers in one omni frame are
// found by colour, matched to the known layout and written as calibration samples for omni fit.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/pipeline/marker_frame_samples.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

// The samples every method needs at the least (ballsight's 8); fewer means the frame or the
// options are wrong, not a calibration.
constexpr std::size_t kMinMatched = 8;

struct MarkersArgs {
  std::string image;
  std::string out;
  std::optional<std::string> center;
  std::string marker_bgr = "220,40,220";
  double bearing_step_deg = 10.0;
  double min_cm = 60.0;
  double max_cm = 460.0;
  double step_cm = 50.0;
  std::optional<double> diameter_cm;
};

void run_markers(const MarkersArgs& args) {
  const cv::Vec3b marker_bgr = parse_bgr(args.marker_bgr, "--marker-bgr");
  MarkerLayout layout;
  layout.bearing_step_deg = args.bearing_step_deg;
  layout.min_distance_m = 0.01 * args.min_cm;
  layout.max_distance_m = 0.01 * args.max_cm;
  layout.distance_step_m = 0.01 * args.step_cm;
  if (args.diameter_cm) {
    require(std::isfinite(*args.diameter_cm) && *args.diameter_cm > 0.0, "--marker-diameter-cm",
            "expected a positive number");
  }
  const std::vector<LayoutMarker> markers =
      markers_of_diameter(layout, args.diameter_cm ? 0.01 * *args.diameter_cm : 0.0);
  const cv::Mat frame = read_image_bgr(args.image);
  const Vec2 center = args.center ? parse_pixel_pair(*args.center, "--center")
                                  : Vec2(0.5 * (frame.cols - 1), 0.5 * (frame.rows - 1));
  const MarkerFrameSamples found = samples_from_marker_frame(frame, markers, marker_bgr, center);
  require(found.samples.size() >= kMinMatched, args.image,
          "matched " + std::to_string(found.samples.size()) + " of " +
              std::to_string(markers.size()) + " layout markers (" + std::to_string(found.blobs) +
              " blobs of the marker colour); check --marker-bgr, --center and the layout options");
  write_polar_samples_csv(args.out, found.samples);
  std::cout << "matched " << found.samples.size() << " of " << markers.size() << " layout markers ("
            << found.blobs << " marker-coloured blobs) -> " << args.out << "\n";
}

}  // namespace

void add_omni_markers_command(CLI::App& omni) {
  auto args = std::make_shared<MarkersArgs>();
  CLI::App* cmd = omni.add_subcommand(
      "markers",
      "Calibration without clicking: find the floor markers of a calibration frame by colour, "
      "match them to the layout (rays every --bearing-step-deg, rings --min-cm..--max-cm every "
      "--step-cm, ray 0 straight ahead) and write samples with bearings for omni fit");
  cmd->add_option("--image", args->image, "Calibration frame (PNG, JPEG)")->required();
  cmd->add_option("--out", args->out, "Samples CSV to write")->required();
  cmd->add_option("--center", args->center,
                  "Image centre CX,CY for the samples' polar coordinates (default: the image's)");
  cmd->add_option("--marker-bgr", args->marker_bgr, "Marker colour B,G,R")->capture_default_str();
  cmd->add_option("--bearing-step-deg", args->bearing_step_deg, "Angle between marker rays, deg")
      ->capture_default_str();
  cmd->add_option("--min-cm", args->min_cm, "Distance of the nearest ring, cm")
      ->capture_default_str();
  cmd->add_option("--max-cm", args->max_cm, "Distance of the farthest ring, cm")
      ->capture_default_str();
  cmd->add_option("--step-cm", args->step_cm, "Distance between rings, cm")->capture_default_str();
  cmd->add_option("--marker-diameter-cm", args->diameter_cm,
                  "The markers' diameter, cm: when given, each blob centroid's perspective shift "
                  "is predicted by a first fit and removed");
  cmd->callback([args] { run_markers(*args); });
}

}  // namespace ballsight::app
