// `ballsight eval tennis-real` and `eval tennis-sim`: the camera-free ball detectors on real
// labelled photos of other people, and on the court simulator's frames.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/eval/tennis_real.hpp"
#include "ballsight/eval/tennis_sim.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

void add_eval_tennis_sim_command(CLI::App& eval) {
  struct Args {
    TennisSimOptions options;
    std::optional<std::string> colours;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = eval.add_subcommand(
      "tennis-sim",
      "The detectors of tennis-real on the court simulator's four camera frames per scene, "
      "labelled from its truth (every tennis ball shown at --min-radius-px or more): recall and "
      "precision per light condition (sun, hard shadow, overcast, indoor) and recall by ball "
      "radius");
  add_seed_option(*cmd, args->options.seed, "Random seed: same seed, same figures");
  add_court_scene_options(*cmd, args->options.scenes, args->options.rig, args->options.court,
                          args->options.scenario);
  cmd->add_option("--min-radius-px", args->options.min_radius_px,
                  "Balls shown smaller are neither labelled nor counted against a detector")
      ->capture_default_str();
  cmd->add_option("--colours", args->colours, "ballsight's colour model (default: built in)")
      ->type_name("FILE");
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->callback([args] {
    if (args->colours) args->options.colours = read_ball_colours(*args->colours);
    const TennisSimResult result = run_tennis_sim(args->options);
    std::cout << (args->json ? tennis_sim_json(result).dump(2) + "\n" : tennis_sim_table(result));
  });
}

}  // namespace

void add_eval_tennis_command(CLI::App& eval) {
  struct Args {
    TennisRealOptions options;
    std::optional<std::string> colours;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = eval.add_subcommand(
      "tennis-real",
      "ballsight's ball detector and the tennis report's (HSV threshold, median filter, contour "
      "centres) on the real labelled photos under real/tennis of the data folder: recall, "
      "precision and centre error per photo, and the time per photo");
  cmd->add_option("--data", args->options.data_dir, "The shared data folder")
      ->capture_default_str();
  cmd->add_option("--colours", args->colours, "ballsight's colour model (default: built in)")
      ->type_name("FILE");
  cmd->add_option("--timing-runs", args->options.timing_runs,
                  "Runs per photo and method; the median time is reported")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->callback([args] {
    if (args->colours) args->options.colours = read_ball_colours(*args->colours);
    const TennisRealResult result = run_tennis_real(args->options);
    std::cout << (args->json ? tennis_real_json(result).dump(2) + "\n" : tennis_real_table(result));
  });
  add_eval_tennis_sim_command(eval);
}

}  // namespace ballsight::app
