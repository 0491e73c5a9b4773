// `ballsight detect fit`: the photo detector's settings fitted to labelled photo sources.
#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/eval/tennis_sim.hpp"
#include "commands.hpp"

namespace ballsight::app {

namespace {

struct FitArgs {
  std::string data = "../shared/data";
  std::vector<std::string> leave_out;
  int rounds = PhotoBallFitOptions{}.rounds;
  int sim_scenes = 0;
  std::string out;
};

void run_fit(const FitArgs& args) {
  const std::filesystem::path root = std::filesystem::path(args.data) / "real" / "tennis";
  std::vector<LabelledPhotos> sources =
      read_photo_sources(root, args.leave_out, "--leave-out").others;
  require(!sources.empty(), root.string(), "holds no labelled source to fit on (*/labels.csv)");
  if (args.sim_scenes > 0) sources.push_back(simulated_fitting_photos(args.sim_scenes));
  PhotoBallFitOptions options;
  options.rounds = args.rounds;
  const PhotoBallFit fit = fit_photo_ball_detector(sources, options);
  nlohmann::json json = photo_ball_fit_json(fit);
  std::string command = "ballsight detect fit --data " + args.data;
  for (const std::string& name : args.leave_out) command += " --leave-out " + name;
  json["command"] = command + " --sim-scenes " + std::to_string(args.sim_scenes) + " --rounds " +
                    std::to_string(args.rounds) + " --out " + args.out;
  write_file_atomic(args.out, json.dump(2) + "\n");
  std::cout << "fitted on " << sources.size() << " source" << (sources.size() == 1 ? "" : "s")
            << " (" << fit.evaluations << " runs): mean F1 " << fixed(fit.mean_f1, 3) << " -> "
            << args.out << "\n";
}

}  // namespace

void add_detect_fit_command(CLI::App& detect) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* cmd = detect.add_subcommand(
      "fit",
      "Fit the ball detector's settings (colour bands, contrast split, score threshold) to the "
      "labelled photo sources under real/tennis of a data folder: the settings of the best mean "
      "F1 over the sources; deterministic");
  cmd->add_option("--data", args->data, "The data folder")->capture_default_str();
  cmd->add_option("--leave-out", args->leave_out, "A source not to fit on (repeatable)")
      ->type_name("NAME");
  cmd->add_option("--sim-scenes", args->sim_scenes,
                  "Also fit on the court simulator's frames of this many scenes (1920x1080, four "
                  "cameras each, with distractors; seed 1), a source like the others")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  cmd->add_option("--rounds", args->rounds, "Passes over the settings")
      ->check(CLI::Range(1, 10))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Settings file to write (JSON; `detect balls --detector`)")
      ->required();
  cmd->callback([args] { run_fit(*args); });
}

}  // namespace ballsight::app
