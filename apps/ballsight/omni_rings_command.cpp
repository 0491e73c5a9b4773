// `ballsight omni rings`: calibration from one spin, no clicking. The rings that floor lines at
// known distances leave in the image of a robot turning on the spot are found along every
// direction and written as calibration samples for omni fit; or, with --line-toward-deg, the
// image of one straight floor line at a known distance (each of its points at d / cos of its
// angle off the line's normal).
#include <cmath>
#include <iostream>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/calib/sample_csv.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/detect/omni_line.hpp"
#include "ballsight/detect/omni_rings.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

// One calibration sample per found ring and direction: ring k (the search looked for as many as
// there are distances) at `distances_cm[k]`.
std::vector<PolarSample> ring_samples(const RingSearch& search,
                                      const std::vector<double>& distances_cm) {
  std::vector<PolarSample> samples;
  for (const RingDirection& direction : search.directions) {
    for (std::size_t k = 0; k < distances_cm.size(); ++k) {
      if (direction.radius_px[k]) {
        samples.push_back({wrap_deg_360(direction.theta_deg), *direction.radius_px[k],
                           distances_cm[k], std::nullopt});
      }
    }
  }
  return samples;
}

// One sample per point of a straight line at `distance_cm` from the robot: d / cos(off normal).
std::vector<PolarSample> line_samples(const LineSearch& search, double distance_cm) {
  std::vector<PolarSample> samples;
  for (const LinePoint& p : search.points) {
    samples.push_back({wrap_deg_360(p.theta_deg), p.radius_px,
                       distance_cm / std::cos(rad_from_deg(p.off_normal_deg)), std::nullopt});
  }
  return samples;
}

struct RingsArgs {
  std::string image;
  std::vector<double> distances_m;
  std::string out;
  std::optional<std::string> center;
  std::optional<std::string> plot;
  std::optional<double> line_toward_deg;
  RingSearchOptions search;
};

void run_line(const RingsArgs& args, const cv::Mat1b& grey, const Vec2& center) {
  require(args.distances_m.size() == 1, "--distances-m",
          "expected one distance with --line-toward-deg (the line's, from the robot's centre)");
  require(std::isfinite(*args.line_toward_deg), "--line-toward-deg", "expected a number");
  LineSearchOptions options;
  options.toward_deg = *args.line_toward_deg;
  options.min_radius_px = args.search.min_radius_px;
  options.tolerance_px = args.search.tolerance_px;
  options.peaks = args.search.peaks();
  LineSearch search;
  try {
    search = find_omni_line(grey, center, options);
  } catch (const InputError& e) {
    throw InputError(args.image + ": " + e.what());
  }
  const double distance_cm = 100.0 * args.distances_m.front();
  const std::vector<PolarSample> samples = line_samples(search, distance_cm);
  write_polar_samples_csv(args.out, samples);
  if (args.plot) write_png_atomic(*args.plot, plot_omni_line(grey, center, search));
  std::cout << samples.size() << " samples along a straight line at " << fixed(distance_cm, 0)
            << " cm -> " << args.out << "\n  normal at " << fixed(search.normal_deg, 2)
            << " deg, nearest radius " << fixed(search.nearest_radius_px, 2) << " px; points "
            << fixed(search.points.front().off_normal_deg, 1) << " to "
            << fixed(search.points.back().off_normal_deg, 1) << " deg off the normal\n";
}

void run_rings(RingsArgs& args) {
  require(!args.distances_m.empty(), "--distances-m", "expected at least one distance");
  std::vector<double> distances_cm;
  for (const double d : args.distances_m) {
    require(
        std::isfinite(d) && d > 0.0 && (distances_cm.empty() || 100.0 * d > distances_cm.back()),
        "--distances-m", "expected positive distances, increasing (the rings from the centre out)");
    distances_cm.push_back(100.0 * d);
  }
  cv::Mat1b grey;
  cv::cvtColor(read_image_bgr(args.image), grey, cv::COLOR_BGR2GRAY);
  const Vec2 center = args.center ? parse_pixel_pair(*args.center, "--center")
                                  : Vec2(0.5 * (grey.cols - 1), 0.5 * (grey.rows - 1));
  if (args.line_toward_deg) return run_line(args, grey, center);
  args.search.distances_m = args.distances_m;
  RingSearch search;
  try {
    search = find_omni_rings(grey, center, args.search);
  } catch (const InputError& e) {
    throw InputError(args.image + ": " + e.what());
  }
  const std::vector<PolarSample> samples = ring_samples(search, distances_cm);
  write_polar_samples_csv(args.out, samples);
  if (args.plot) write_png_atomic(*args.plot, plot_omni_rings(grey, center, search));
  std::cout << samples.size() << " samples from " << search.directions.size() << " directions x "
            << distances_cm.size() << " rings (" << search.hidden << " hidden, " << search.ambiguous
            << " ambiguous) -> " << args.out << "\n  the rings' centre "
            << fixed(search.decentring_px.x(), 0) << ", " << fixed(search.decentring_px.y(), 0)
            << " px from the given one\n";
  for (std::size_t k = 0; k < distances_cm.size(); ++k) {
    const RingCurve& ring = search.rings[k];
    std::cout << "  ring " << k + 1 << " at " << fixed(distances_cm[k], 0) << " cm: median radius "
              << fixed(ring.median_radius_px, 2) << " px, found in "
              << fixed(100.0 * ring.found_fraction, 0) << " % of the directions, "
              << fixed(ring.residual_px, 2) << " px from its curve (median)\n";
  }
  for (const BlockedSpan& span : search.blocked) {
    std::cout << "  no ring from " << fixed(span.from_deg, 1) << " to " << fixed(span.to_deg, 1)
              << " deg (" << span.directions << " directions: a strut or the robot)\n";
  }
}

}  // namespace

void add_omni_rings_command(CLI::App& omni) {
  auto args = std::make_shared<RingsArgs>();
  CLI::App* cmd = omni.add_subcommand(
      "rings",
      "Calibration from one spin, no clicking: find the rings that floor lines at known distances "
      "leave in the image of a robot turning on the spot, along every direction, and write "
      "calibration samples for omni fit (directions where a ring is hidden or ambiguous are "
      "left out); or, with --line-toward-deg, the image of one straight floor line");
  cmd->add_option("--image", args->image, "The ring (or line) image (PNG, JPEG; read as grey)")
      ->required();
  cmd->add_option("--distances-m", args->distances_m,
                  "The lines' distances from the robot's centre, m, comma-separated, increasing")
      ->delimiter(',')
      ->required();
  cmd->add_option("--out", args->out, "Samples CSV to write")->required();
  cmd->add_option("--center", args->center,
                  "Image centre CX,CY: the robot's turning centre in the image (default: the "
                  "image's)");
  CLI::Option* directions =
      cmd->add_option("--directions", args->search.directions, "Directions searched, evenly spread")
          ->capture_default_str();
  cmd->add_option("--min-radius-px", args->search.min_radius_px,
                  "Radius where the search starts (inside: the robot)")
      ->capture_default_str();
  cmd->add_option("--min-contrast", args->search.min_contrast,
                  "Grey levels a ring (or the line) stands above its background")
      ->capture_default_str();
  cmd->add_option("--max-width-px", args->search.max_width_px,
                  "The widest ring's (or the line's) image across a direction, px")
      ->capture_default_str();
  cmd->add_option("--tolerance-px", args->search.tolerance_px,
                  "How far a ring's (or the line's) peak may lie from where it runs")
      ->capture_default_str();
  cmd->add_option("--line-toward-deg", args->line_toward_deg,
                  "The image holds one straight floor line, not rings: at the one distance of "
                  "--distances-m, nearest the robot in about this image direction (deg, 90: up)")
      ->type_name("DEG")
      ->excludes(directions);
  cmd->add_option("--plot", args->plot,
                  "Also write a PNG of the rings (or the line) found, and the rejected directions")
      ->type_name("PNG");
  cmd->callback([args] { run_rings(*args); });
}

}  // namespace ballsight::app
