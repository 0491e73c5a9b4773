#pragma once
// The demo's closed loop (`ballsight demo`) as values: what a run of one system was and its score
// on the court's record (service/loop_truth.hpp), and the runs side by side. Running them (the
// service and the robot as two processes) is the command line's business:
// apps/ballsight/loop_demo.hpp.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ballsight/service/loop_truth.hpp"
#include "ballsight/viz/report.hpp"

namespace ballsight {

struct LoopDemoOptions {
  std::uint64_t seed = 1;
  int balls = 20;
  double max_time_s = 150.0;  // simulated, per run
  bool faults = true;         // the fourth run, with a camera failure and both restarts

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
  int unreachable = 0;             // balls the robot gave up on
  std::vector<TruthEvent> events;  // the record's and the demo's own (what it did, when)
  double wall_s = 0.0;
  std::filesystem::path dir;  // serve and robot logs, the record, the robot's summaries
  /// Each service process's recording (serve --record, docs/recording.md), in order: a service
  /// that was killed left its file cut short, readable up to its last complete chunk.
  std::vector<std::filesystem::path> recordings;
};

/// Runs every system into out_dir/loop/<name>/; `progress` hears a line now and then.
using LoopDemoRunner = std::function<std::vector<LoopDemoRun>(
    const LoopDemoOptions& options, const std::filesystem::path& out_dir,
    const std::function<void(const std::string&)>& progress)>;

/// The runs side by side: balls collected, time to collect all, distance, contacts, unload trips,
/// balls given up, latency, missed updates, wall time.
ReportTable loop_demo_table(const std::vector<LoopDemoRun>& runs);

/// The result that matters, a row per run: balls collected, time to collect them all, distance,
/// the faults it went through.
ReportTable loop_result_table(const std::vector<LoopDemoRun>& runs);

}  // namespace ballsight
