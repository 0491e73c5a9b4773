#pragma once
// The main job: ballsight end to end on built-in simulated data, with a report a person can read.
// It renders both simulated rigs, calibrates the omni camera from the markers it finds and places
// the ball in every frame (ballsight's pipeline beside the paper's), and calibrates and runs both
// court methods against the truth, plans a collection route, and closes the loop: the service
// and the robot as two processes collect a simulated court's balls (`run_loop`: the command line
// starts them, apps/ballsight/loop_demo.hpp).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "ballsight/eval/loop_demo.hpp"

namespace ballsight {

struct DemoOptions {
  std::uint64_t seed = 1;
  int omni_frames = 4;            // frame 0 is the calibration frame with floor markers
  int court_scenes = 1;           // four camera views each
  int loop_balls = 20;            // the closed loop's scene
  double loop_max_time_s = 90.0;  // simulated, per system
  bool loop_faults = true;        // the closed loop once more with faults
  /// The web pages' folder: the report inlines its style sheet and the court map's script for
  /// the loop's replay ("" or missing: a plain page, the replay left out with a note).
  std::filesystem::path web_dir;
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
/// `run_loop` runs the closed loop's systems; `progress` hears what the demo is doing (the closed
/// loop's simulated time, balls left).
DemoResult run_demo(const DemoOptions& options, const std::filesystem::path& out_dir,
                    const LoopDemoRunner& run_loop,
                    const std::function<void(const std::string&)>& progress = {});

}  // namespace ballsight
