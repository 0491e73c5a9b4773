#pragma once
// The main job: ballsight end to end on built-in simulated data, with a report a person can read.
// It renders both simulated rigs, calibrates the omni camera from the markers it finds and places
// the ball in every frame (ballsight's pipeline beside the paper's), and calibrates and runs both
// court methods against the truth; later stages (routes, service) add their sections here.

#include <cstdint>
#include <filesystem>
#include <string>

namespace ballsight {

struct DemoOptions {
  std::uint64_t seed = 1;
  int omni_frames = 4;   // frame 0 is the calibration frame with floor markers
  int court_scenes = 1;  // four camera views each
  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct DemoResult {
  std::filesystem::path report_html;
  std::filesystem::path report_markdown;
  int images_written = 0;
};

/// Runs the demo into `out_dir` (created if missing): omni/ and court/ data sets, report.html and
/// report.md.
DemoResult run_demo(const DemoOptions& options, const std::filesystem::path& out_dir);

}  // namespace ballsight
