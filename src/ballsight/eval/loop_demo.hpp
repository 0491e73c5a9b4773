#pragma once
// The demo's closed loop (`ballsight demo`): for each system (eval/loop_eval.hpp) the navigation
// service on the simulated court (`ballsight serve --sim`) and the robot (`ballsight robot`) as
// two processes talking over loopback HTTP/WebSocket, until every ball is collected, the robot
// sees none left, or the time limit. A last run repeats ballsight's with faults: a camera dies,
// the service is killed and started again (the court resumes from its record), the robot is
// killed and started again. Each run is scored on the court's record (eval/loop_truth.hpp).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ballsight/eval/loop_truth.hpp"

namespace ballsight {

struct LoopDemoOptions {
  std::uint64_t seed = 1;
  int balls = 20;
  double max_time_s = 150.0;      // simulated, per run
  bool faults = true;             // the fourth run, with a camera failure and both restarts
  std::filesystem::path program;  // ballsight itself (own_executable())

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct LoopDemoRun {
  std::string name;  // the system, or "ballsight, with faults"
  LoopTruth truth;
  LoopScore score;
  std::vector<std::uint64_t> seqs;  // updates at the robot, over all its processes
  std::vector<double> latency_ms;   // frames captured -> update parsed at the robot (wall)
  std::uint64_t gaps = 0;           // updates published but never delivered to the robot
  int reconnects = 0;
  std::vector<TruthEvent> events;  // the record's and the demo's own (what it did, when)
  double wall_s = 0.0;
  std::filesystem::path dir;  // serve and robot logs, the record, the robot's summaries
};

/// Runs every system into out_dir/loop/<name>/; `progress` hears a line now and then.
std::vector<LoopDemoRun> run_loop_demo(const LoopDemoOptions& options,
                                       const std::filesystem::path& out_dir,
                                       const std::function<void(const std::string&)>& progress);

/// The runs side by side: balls collected, time to collect all, distance, latency, gaps.
std::string loop_demo_table(const std::vector<LoopDemoRun>& runs);

}  // namespace ballsight
