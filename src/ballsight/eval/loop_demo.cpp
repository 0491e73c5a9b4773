#include "ballsight/eval/loop_demo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/court_metrics.hpp"

namespace ballsight {

void LoopDemoOptions::validate() const {
  require(balls >= 1 && balls <= 60, "demo", "loop balls must be 1..60");
  require(std::isfinite(max_time_s) && max_time_s > 0.0, "demo", "loop max time must be positive");
}

ReportTable loop_demo_table(const std::vector<LoopDemoRun>& runs) {
  ReportTable table{
      "Each run in detail (contacts: ticks of 0.1 s in which the net or the fence "
      "stopped the robot; latency: frames captured to the update at the robot, wall)",
      {"system", "collected", "time to all (s)", "distance (m)", "contacts", "unloads", "given up",
       "latency p50 / p99 / max (ms)", "missed updates", "wall (s)"},
      {}};
  for (const LoopDemoRun& r : runs) {
    const double max_ms =
        r.latency_ms.empty() ? 0.0 : *std::max_element(r.latency_ms.begin(), r.latency_ms.end());
    table.rows.push_back({r.name,
                          std::to_string(r.score.collected) + " / " + std::to_string(r.score.balls),
                          r.score.all ? fixed(r.score.time_s, 1) : "not all",
                          fixed(r.score.distance_m, 1), std::to_string(r.score.blocked_ticks),
                          std::to_string(r.score.unloads), std::to_string(r.unreachable),
                          fixed(quantile(r.latency_ms, 0.5), 1) + " / " +
                              fixed(quantile(r.latency_ms, 0.99), 1) + " / " + fixed(max_ms, 1),
                          std::to_string(r.gaps), fixed(r.wall_s, 1)});
  }
  return table;
}

ReportTable loop_result_table(const std::vector<LoopDemoRun>& runs) {
  ReportTable table{"",
                    {"system", "balls collected", "time to collect all (s)", "distance (m)",
                     "faults it went through"},
                    {}};
  for (const LoopDemoRun& r : runs) {
    std::string faults;
    for (const TruthEvent& e : r.events) {
      if (e.what.find("killed") == std::string::npos &&
          e.what.find("failed") == std::string::npos) {
        continue;
      }
      faults += (faults.empty() ? "" : "; ") + e.what;
    }
    table.rows.push_back(
        {r.name, std::to_string(r.score.collected) + " of " + std::to_string(r.score.balls),
         r.score.all ? fixed(r.score.time_s, 1) : "not all in time", fixed(r.score.distance_m, 1),
         faults.empty() ? "none" : faults});
  }
  return table;
}

}  // namespace ballsight
