// `ballsight court calibrate`: every camera of a site finds the reference balls in a still frame
// of its source and its pose goes into its calibration file (docs/site-file.md).

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/pipeline/court_calibration.hpp"
#include "ballsight/world/site.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

struct CourtCalibrateArgs {
  std::string site;
  StillFrameOptions frame;
  double retry_wait_s = 0.5;
};

void print_report(const CameraPoseReport& r) {
  const Vec3 center = r.pose.camera_from_field.inverse().translation;
  std::cout << "camera " << r.camera << " (" << r.source << "): " << r.blob_count << " blobs, "
            << r.pose.matches.size() << " of " << r.references.size()
            << " reference balls, reprojection rms " << fixed(r.pose.rms_px, 3) << " px (max "
            << fixed(r.pose.max_px, 3) << "); camera at (" << fixed(center.x(), 3) << ", "
            << fixed(center.y(), 3) << ", " << fixed(center.z(), 3) << ") m\n";
  std::cout << "  matched:";
  for (const ReferenceMatch& m : r.pose.matches) {
    std::cout << " " << r.references[m.reference].name << " " << fixed(m.residual_px, 2) << " px";
  }
  std::cout << "\n  not found:";
  for (std::size_t i : r.pose.unmatched) std::cout << " " << r.references[i].name;
  std::cout << (r.pose.unmatched.empty() ? " none" : "") << "\n";
}

void calibrate_court(CourtCalibrateArgs args) {
  require(args.retry_wait_s >= 0.0 && args.retry_wait_s <= 60.0, "--retry-wait",
          "must be within [0, 60] seconds");
  args.frame.backoff.initial =
      std::chrono::milliseconds(static_cast<int>(1000.0 * args.retry_wait_s));
  args.frame.backoff.max = std::max(args.frame.backoff.max, args.frame.backoff.initial);
  args.frame.validate();
  const Site site = read_site(args.site);
  CourtCalibrationOptions options;
  options.frame = args.frame;
  const SiteCalibration result = calibrate_site(site, options);
  for (const CameraPoseReport& report : result.calibrated) {
    print_report(report);
    if (result.written) std::cout << "  wrote " << report.calibration_file.string() << "\n";
  }
  if (result.written) return;
  std::string names;
  for (const CameraCalibrationFailure& failure : result.failed) {
    std::cerr << "ballsight: " << failure.error << "\n";
    names += (names.empty() ? "" : ", ") + failure.camera;
  }
  throw InputError(std::to_string(result.failed.size()) + " of " +
                   std::to_string(site.cameras.size()) + " cameras failed (" + names +
                   "); no calibration file written");
}

}  // namespace

void add_court_calibrate_command(CLI::App& court) {
  auto args = std::make_shared<CourtCalibrateArgs>();
  CLI::App* cmd = court.add_subcommand(
      "calibrate",
      "Pose of every site camera from the reference balls in a still frame of its source, written "
      "into its calibration file");
  cmd->add_option("--site", args->site, "Site file (YAML, docs/site-file.md)")->required();
  cmd->add_option("--attempts", args->frame.attempts,
                  "Tries to open a device or URL source and read its frames")
      ->capture_default_str();
  cmd->add_option("--retry-wait", args->retry_wait_s,
                  "Seconds before the second try, doubling for each further one (at most 4 s)")
      ->capture_default_str();
  cmd->add_option("--live-frames", args->frame.live_frames,
                  "Frames of a device or URL source averaged into the still")
      ->capture_default_str();
  cmd->callback([args] { calibrate_court(*args); });
}

}  // namespace ballsight::app
