// `ballsight eval detect-real` and `eval tennis-sim`: the camera-free ball detectors on real
// labelled photos of other people, and on the court simulator's frames.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/eval/detect_real.hpp"
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
      "The detectors of detect-real on the court simulator's four camera frames per scene, "
      "labelled from its truth (every tennis ball shown at --min-radius-px or more): recall and "
      "precision per light condition (sun, hard shadow, overcast, indoor) and recall by ball "
      "radius");
  add_seed_option(*cmd, args->options.seed, "Random seed: same seed, same figures");
  add_court_scene_options(*cmd, args->options.scenes, args->options.rig, args->options.court,
                          args->options.scenario);
  cmd->add_option("--min-radius-px", args->options.min_radius_px,
                  "Balls shown smaller are neither labelled nor counted against a detector")
      ->capture_default_str();
  cmd->add_option("--colours", args->colours,
                  "ballsight's colour model (default: the shipped detector's)")
      ->type_name("FILE");
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->callback([args] {
    if (args->colours) args->options.detector.colours = read_ball_colours(*args->colours);
    const TennisSimResult result = run_tennis_sim(args->options);
    std::cout << (args->json ? tennis_sim_json(result).dump(2) + "\n" : tennis_sim_table(result));
  });
}

}  // namespace

void add_eval_tennis_command(CLI::App& eval) {
  struct Args {
    DetectRealOptions options;
    std::optional<std::string> colours;
    std::optional<std::string> detector;
    std::optional<std::string> verifier;
    std::optional<std::string> draw;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = eval.add_subcommand(
      "detect-real",
      "What a user on an unseen court gets: the ball detector on each real labelled source under "
      "real/tennis of the data folder, fitted without that source (leave one source out), as "
      "shipped, and the tennis report's HSV detector: recall, precision, F1, centre error and "
      "misses by cause per source");
  cmd->add_option("--data", args->options.data_dir, "The shared data folder")
      ->capture_default_str();
  cmd->add_option("--colours", args->colours,
                  "The shipped detector's colour model (default: built in)")
      ->type_name("FILE");
  cmd->add_option("--detector", args->detector,
                  "Score these settings (`detect fit`'s output) as the shipped detector (default: "
                  "built in); --colours then replaces their colour model")
      ->type_name("FILE");
  cmd->add_option("--draw", args->draw,
                  "Draw each image's labels and detections into this folder "
                  "(<method>/<source>/<image>.png)")
      ->type_name("DIR");
  cmd->add_option("--sim-scenes", args->options.sim_scenes,
                  "Scenes of the court simulator each leave-one-source-out fit also fits on (as "
                  "the shipped settings were)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  CLI::Option* methods =
      cmd->add_option("--methods", args->options.methods, "Which methods to run (comma-separated)")
          ->delimiter(',')
          ->check(CLI::IsMember(
              std::vector<std::string>(kDetectRealMethods.begin(), kDetectRealMethods.end())))
          ->capture_default_str();
  cmd->add_option("--verifier", args->verifier,
                  "A ball verifier (ONNX, scripts/train_ball_verifier.py): also score the "
                  "\"verified\" method")
      ->type_name("FILE");
  cmd->add_flag("--json", args->json, "Print JSON instead of a table");
  cmd->callback([args, methods] {
    if (args->verifier) {
      args->options.verifier = *args->verifier;
      if (methods->count() == 0) args->options.methods.emplace_back(kDetectRealMethods[3]);
    }
    if (args->detector) args->options.shipped = read_photo_ball_options(*args->detector);
    if (args->colours) args->options.shipped.colours = read_ball_colours(*args->colours);
    if (args->draw) args->options.draw_dir = *args->draw;
    const DetectRealResult result = run_detect_real(args->options);
    std::cout << (args->json ? detect_real_json(result).dump(2) + "\n" : detect_real_table(result));
  });
  add_eval_tennis_sim_command(eval);
}

}  // namespace ballsight::app
