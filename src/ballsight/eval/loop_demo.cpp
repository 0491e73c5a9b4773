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

std::string loop_demo_table(const std::vector<LoopDemoRun>& runs) {
  std::string text =
      "system               collected  time to all (s)  distance (m)  contacts  unloads  given up  "
      "latency p50/p99/max (ms)  missed updates  wall (s)\n";
  for (const LoopDemoRun& r : runs) {
    char line[256];
    std::snprintf(
        line, sizeof line,
        "%-20s %4d / %-3d %16s %13.1f %9d %8d %9d %10.1f / %.1f / %.1f %14llu %9.1f\n",
        r.name.c_str(), r.score.collected, r.score.balls,
        r.score.all ? fixed(r.score.time_s, 1).c_str() : "not all", r.score.distance_m,
        r.score.blocked_ticks, r.score.unloads, r.unreachable, quantile(r.latency_ms, 0.5),
        quantile(r.latency_ms, 0.99),
        r.latency_ms.empty() ? 0.0 : *std::max_element(r.latency_ms.begin(), r.latency_ms.end()),
        static_cast<unsigned long long>(r.gaps), r.wall_s);
    text += line;
  }
  return text;
}

}  // namespace ballsight
