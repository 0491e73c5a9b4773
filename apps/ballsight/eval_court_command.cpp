// `ballsight eval court`: the report's court pipeline and ballsight's on simulated scenes, each
// calibrated from rendered chessboards and reference balls, scored against the truth
// (docs/court-eval.md).

#include <iostream>
#include <memory>
#include <string>

#include "ballsight/eval/court_eval.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct EvalCourtArgs {
  CourtEvalOptions options;
  bool json = false;
  std::string plot_dir;
  bool no_net = false;
};

void run_eval_court(const EvalCourtArgs& args) {
  CourtEvalOptions options = args.options;
  if (!args.plot_dir.empty()) options.plot_dir = args.plot_dir;
  options.court.net.enabled = !args.no_net;
  const CourtEvalReport report = run_court_eval(options);
  if (args.json) {
    std::cout << court_eval_json(report).dump(2) << "\n";
  } else {
    std::cout << court_eval_text(report);
  }
}

}  // namespace

void add_eval_court_command(CLI::App& eval) {
  auto args = std::make_shared<EvalCourtArgs>();
  args->options.rig.width = sim::kReportCameraWidth;
  args->options.rig.height = sim::kReportCameraHeight;
  CLI::App* cmd = eval.add_subcommand(
      "court",
      "Both court methods (seed: the report's pipeline; ballsight) on simulated scenes with 20-60 "
      "balls, clusters, balls hidden by the robot and lighting changes, each calibrated from "
      "rendered chessboards and reference balls: recall, precision, duplicates, ball and robot "
      "errors");
  add_seed_option(*cmd, args->options.seed, "Random seed: same seed, same figures");
  add_court_scene_options(*cmd, args->options.scenes, args->options.rig, args->options.court,
                          args->options.scenario);
  cmd->add_flag("--no-net", args->no_net,
                "Scenes on a court without a net (the simulator of before the net)");
  cmd->add_flag("--json", args->json,
                "JSON: {\"methods\": {\"seed\": {...}, \"ballsight\": {...}}, ..., \"wall_clock\": "
                "{\"methods\": {...: {\"frame_set_ms_mean\"}}}} (all but wall_clock: the same "
                "every run of a seed)");
  CLI::Option* plot_dir =
      cmd->add_option("--plot-dir", args->plot_dir,
                      "Write each camera's view with detections and a field map of truth vs "
                      "estimates for the first scenes");
  cmd->add_flag("--plot-mistakes", args->options.plot_mistakes,
                "With --plot-dir: also the pictures of every scene where ballsight missed a ball "
                "or made a duplicate or false estimate (the text lists ballsight's, --json every "
                "method's under \"mistakes\")")
      ->needs(plot_dir);
  cmd->callback([args] { run_eval_court(*args); });
}

}  // namespace ballsight::app
