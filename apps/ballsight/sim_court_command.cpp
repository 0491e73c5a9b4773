// `ballsight sim court`: renders tennis-court scenes seen by the four corner cameras, with their
// truth, and optionally chessboard calibration views of each camera (docs/sim-court.md).

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_dataset.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct SimCourtArgs {
  std::string out_dir;
  sim::CourtDatasetOptions dataset;
  std::optional<int> balls;
  std::optional<double> brightness;
  bool no_shadow = false;
  bool no_wear = false;
  bool distractors = false;
  bool no_net = false;
};

void run_sim_court(const SimCourtArgs& args) {
  sim::CourtDatasetOptions options = args.dataset;
  options.scenario.ball_count = args.balls;
  options.scenario.brightness_gain = args.brightness;
  options.scenario.shadow = !args.no_shadow;
  if (args.no_wear) options.scenario.worn_share_max = 0.0;
  options.scenario.distractors = args.distractors;
  options.court.net.enabled = !args.no_net;
  const auto files = sim::write_court_dataset(options, args.out_dir);
  std::cout << "wrote " << files.size() << " files to " << args.out_dir << "\n";
}

}  // namespace

void add_sim_court_command(CLI::App& sim) {
  auto args = std::make_shared<SimCourtArgs>();
  args->dataset.rig.width = sim::kReportCameraWidth;
  args->dataset.rig.height = sim::kReportCameraHeight;
  CLI::App* cmd = sim.add_subcommand(
      "court",
      "Tennis court seen by four corner-pole cameras: court_KKKK_camC.png and court_KKKK.json "
      "(truth) per scene; with --chessboards, camC_board_VV.png and chessboards.json");
  cmd->add_option("--out", args->out_dir, "Output folder (created if missing)")->required();
  add_seed_option(*cmd, args->dataset.seed, "Random seed: same seed, same bytes");
  cmd->add_option("--scenes", args->dataset.scenes, "Number of scenes [0, 9999]")
      ->capture_default_str();
  cmd->add_option("--balls", args->balls,
                  "Tennis balls per scene [0, 200] (default: random 20-60)");
  cmd->add_option("--width", args->dataset.rig.width, "Image width, px")->capture_default_str();
  cmd->add_option("--height", args->dataset.rig.height, "Image height, px")->capture_default_str();
  cmd->add_option("--chessboards", args->dataset.chessboard_views,
                  "Chessboard views per camera [0, 99]")
      ->capture_default_str();
  cmd->add_option("--noise", args->dataset.scenario.noise_sigma,
                  "Sensor noise sigma, grey levels [0, 64]")
      ->capture_default_str();
  cmd->add_option("--brightness", args->brightness,
                  "Brightness gain (0, 4] (default: random 0.8-1.2 per scene)");
  add_court_look_options(*cmd, args->dataset.court, args->dataset.scenario);
  cmd->add_flag("--no-shadow", args->no_shadow, "No shadow band across the court");
  cmd->add_flag("--no-wear", args->no_wear, "No worn (paler) balls");
  cmd->add_flag("--distractors", args->distractors,
                "Fallen leaves and a water bottle of a ball's colour on some scenes");
  cmd->add_flag("--no-net", args->no_net, "No net across the court (the simulator of before)");
  cmd->callback([args] { run_sim_court(*args); });
}

}  // namespace ballsight::app
