#pragma once
// `ballsight eval plan`: every route planner on simulated ball layouts of the standard court
// (plan_layouts.hpp) from random robot poses: route time and length, planning time, for n <= 12
// the gap to the exact optimum (Held-Karp, visits at the balls: ballsight runs without sweeping
// for that comparison), for n = 50 and 100 the gap to a long run (effort x100), and ballsight's
// saving against the report's rule and nearest neighbour (docs/route-planning.md).

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/eval/plan_layouts.hpp"
#include "ballsight/viz/report.hpp"

namespace ballsight::eval {

struct PlanEvalOptions {
  std::uint64_t seed = 1;
  std::vector<int> sizes{5, 8, 12, 20, 50, 100, 200, 400};
  std::vector<BallLayout> layouts{std::begin(kBallLayouts), std::end(kBallLayouts)};
  double long_run_effort = 100.0;
  std::optional<std::filesystem::path> plot_dir;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Mean and worst of one figure over the trials.
struct Spread {
  double mean = 0.0;
  double max = 0.0;
  int count = 0;
  void add(double value);
};

struct PlannerFigures {
  Spread time_s, length_m, plan_ms;
  Spread gap_to_optimal_pct;   // n <= 12
  Spread gap_to_long_run_pct;  // n = 50, 100 (ballsight)
};

/// Figures of each planner ("priority", "nearest", "ballsight", and ballsight visiting every
/// ball's centre, "ballsight_centres", or the world model's collection sites, "ballsight_sites")
/// per n, over every layout, and per layout.
struct PlanEvalReport {
  PlanEvalOptions options;
  std::map<std::string, std::map<int, PlannerFigures>> by_n;
  std::map<std::string, std::map<std::string, std::map<int, PlannerFigures>>> by_layout;
  int trials = 0;
};

/// Trials per layout for `n` balls.
int plan_eval_trials(int n);

PlanEvalReport run_plan_eval(const PlanEvalOptions& options);

/// The report's rule, nearest neighbour and ballsight on one layout of `n` balls, their routes
/// drawn into `png`; a row per planner: its name, time (s), length (m), planning time (ms).
ReportTable plan_comparison(BallLayout layout, int n, std::uint64_t seed,
                            const std::filesystem::path& png);
nlohmann::json plan_eval_json(const PlanEvalReport& report);
std::string plan_eval_text(const PlanEvalReport& report);

}  // namespace ballsight::eval
