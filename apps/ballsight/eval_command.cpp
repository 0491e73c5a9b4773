// `ballsight eval ...`: the experiments that measure ballsight against the papers' methods.
#include <iostream>
#include <memory>
#include <optional>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/eval/mirror_curves.hpp"
#include "ballsight/eval/omni_experiment.hpp"
#include "ballsight/eval/omni_real.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/viz/estimate_plot.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

namespace {

void add_eval_omni_real_command(CLI::App& eval) {
  struct Args {
    OmniRealOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* real = eval.add_subcommand(
      "omni-real",
      "The omni methods on real calibration data of other teams (real/omni under the data "
      "folder, and the paper's Table I): held-out median error by direction and by whole "
      "distance, each method fitted on the same split");
  real->add_option("--data", args->options.data_dir, "The shared data folder")
      ->capture_default_str();
  real->add_option("--methods", args->options.methods,
                   "Methods to run, comma-separated: poly, paper-mlp, ballsight")
      ->delimiter(',')
      ->capture_default_str();
  real->add_option("--max-distance-folds", args->options.max_distance_folds,
                   "Held-out whole distances per set at most, evenly spread")
      ->capture_default_str();
  real->add_option("--jobs", args->options.jobs, "Fits run at once")->capture_default_str();
  real->add_flag("--json", args->json, "Print JSON instead of a table");
  real->callback([args] {
    args->options.progress = [](const std::string& line) { std::cerr << line << std::endl; };
    const OmniRealResult result = run_omni_real(args->options);
    require(!result.sets.empty(), args->options.data_dir.string(),
            "holds none of the real omni sets (looked for " +
                std::to_string(result.missing.size()) + " files)");
    std::cout << (args->json ? omni_real_json(result).dump(2) + "\n" : omni_real_table(result));
  });
}

void add_eval_mirror_curves_command(CLI::App& eval) {
  struct Args {
    std::filesystem::path data_dir = OmniRealOptions().data_dir;
    bool json = false;
    std::optional<std::string> plot;
  };
  auto args = std::make_shared<Args>();
  CLI::App* curves = eval.add_subcommand(
      "mirror-curves",
      "The simulator's mirrors beside real ones: the image radius of a floor point against its "
      "distance, for each simulated mirror kind and each real calibration set (real/omni under "
      "the data folder, and the paper's Table I)");
  curves->add_option("--data", args->data_dir, "The shared data folder")->capture_default_str();
  curves->add_flag("--json", args->json, "Print JSON instead of a table");
  curves->add_option("--plot", args->plot, "Also write a PNG of the curves")->type_name("PNG");
  curves->callback([args] {
    std::vector<std::string> missing;
    std::vector<MirrorCurve> all = simulated_mirror_curves();
    for (MirrorCurve& c : real_mirror_curves(load_real_omni_sets(args->data_dir, missing)))
      all.push_back(std::move(c));
    if (args->plot) write_png_atomic(*args->plot, plot_mirror_curves(all));
    std::cout << (args->json
                      ? mirror_curves_json(all).dump(2) + "\n"
                      : mirror_curves_table(all, {0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0}));
    for (const std::string& file : missing) std::cerr << "not found, left out: " << file << "\n";
  });
}

}  // namespace

void add_eval_commands(CLI::App& eval) {
  add_eval_omni_real_command(eval);
  add_eval_mirror_curves_command(eval);
  struct Args {
    OmniExperimentOptions options;
    std::string mirror = "unified";
    bool json = false;
    std::optional<std::string> plot;
  };
  auto args = std::make_shared<Args>();
  CLI::App* omni = eval.add_subcommand(
      "omni",
      "The omnivision paper's experiment (Section V) on the simulator: calibrate poly, paper-mlp "
      "and ballsight from clicked markers on a misaligned camera, locate a ball at (400, 600) cm "
      "from 120, 200 and 285 cm in 30 degree turns; mean error and std of x and y per distance, "
      "beside the true mapping (oracle)");
  add_seed_option(*omni, args->options.seed, "Seed (click and sensor noise)");
  omni->add_option("--tilt-deg", args->options.tilt_deg, "Camera axis tilt, 0..10 deg")
      ->capture_default_str();
  omni->add_option("--click-noise-px", args->options.click_noise_px, "Marker click noise, px")
      ->capture_default_str();
  omni->add_option("--measured-height-sigma-cm", args->options.measured_height_sigma_cm,
                   "Also give ballsight the camera's viewpoint height as measured on the robot, "
                   "with a normal error of this standard deviation (cm)");
  omni->add_option("--mirror", args->mirror, kMirrorHelp)->capture_default_str();
  omni->add_option("--methods", args->options.methods,
                   "Methods to run, comma-separated: poly, paper-mlp, ballsight, oracle")
      ->delimiter(',')
      ->capture_default_str();
  omni->add_flag("--json", args->json,
                 "Print JSON instead of a table (the fits' times under \"wall_clock\"; the "
                 "rest the same every run of a seed)");
  omni->add_option("--plot", args->plot, "Also write a PNG of every estimate around the ball")
      ->type_name("PNG");
  omni->callback([args] {
    args->options.mirror = parse_mirror_kind(args->mirror, "--mirror");
    const OmniExperimentResult result = run_omni_experiment(args->options);
    if (args->plot) {
      write_png_atomic(*args->plot,
                       plot_ball_estimates(result.options.ball_cm, result.options.distances_cm,
                                           estimate_layers(result)));
    }
    std::cout << (args->json ? omni_experiment_json(result).dump(2) + "\n"
                             : omni_experiment_table(result));
  });
}

}  // namespace ballsight::app
