#pragma once
// The demo's closed loop (`ballsight demo`): for each system (eval/loop_eval.hpp) the navigation
// service on the simulated court (`ballsight serve --sim`) and the robot (`ballsight robot`) as
// two processes of this program talking over loopback HTTP/WebSocket, until every ball is
// collected, the robot sees none left, or the time limit. A last run repeats ballsight's with
// faults: a camera dies, the service is killed and started again (the court resumes from its
// record), the robot is killed and started again. Each run is scored on the court's record
// (service/loop_truth.hpp).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ballsight/eval/loop_demo.hpp"

namespace ballsight::app {

/// Runs every system into out_dir/loop/<name>/ (an eval::LoopDemoRunner); `progress` hears a line
/// now and then.
std::vector<LoopDemoRun> run_loop_demo(const LoopDemoOptions& options,
                                       const std::filesystem::path& out_dir,
                                       const std::function<void(const std::string&)>& progress);

}  // namespace ballsight::app
