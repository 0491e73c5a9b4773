// `ballsight eval plan`: the route planners side by side on simulated ball layouts
// (docs/route-planning.md).

#include <iostream>
#include <memory>
#include <string>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/eval/plan_eval.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct EvalPlanArgs {
  eval::PlanEvalOptions options;
  std::string sizes;
  std::string plot_dir;
  bool json = false;
};

void run_eval_plan(const EvalPlanArgs& args) {
  eval::PlanEvalOptions options = args.options;
  if (!args.sizes.empty()) {
    options.sizes.clear();
    for (const CsvField& item : split_csv_fields(args.sizes)) {
      options.sizes.push_back(
          static_cast<int>(parse_numbers(std::string(item.text), 1, "--sizes", "N,N,...")[0]));
    }
  }
  if (!args.plot_dir.empty()) options.plot_dir = args.plot_dir;
  const eval::PlanEvalReport report = eval::run_plan_eval(options);
  std::cout << (args.json ? eval::plan_eval_json(report).dump(2) + "\n"
                          : eval::plan_eval_text(report));
}

}  // namespace

void add_eval_plan_command(CLI::App& eval) {
  auto args = std::make_shared<EvalPlanArgs>();
  CLI::App* cmd = eval.add_subcommand(
      "plan",
      "The route planners (the report's priority rule, nearest neighbour, ballsight) on simulated "
      "ball layouts (uniform, practice clusters, near the net) of 5 to 400 balls: route time and "
      "length, gap to the exact optimum (n <= 12) and to a long run (n = 50, 100), planning time");
  add_seed_option(*cmd, args->options.seed, "Random seed: same seed, same layouts");
  cmd->add_option("--sizes", args->sizes,
                  "Ball counts, comma-separated (default 5,8,12,20,50,"
                  "100,200,400)");
  cmd->add_flag(
      "--json", args->json,
      "JSON: {\"planners\": {\"<name>\": {\"by_n\": {\"<n>\": {...}}}}, \"layouts\": "
      "..., \"ballsight_time_saved_pct\": ..., \"wall_clock\": {every plan_ms_mean, at its "
      "path}} (all but wall_clock: the same every run of a seed)");
  cmd->add_option("--plot-dir", args->plot_dir,
                  "Write the three planners' routes for the first layout of 20, 50 and 100 balls");
  cmd->callback([args] { run_eval_plan(*args); });
}

}  // namespace ballsight::app
