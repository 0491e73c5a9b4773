// `ballsight demo`: the main job on built-in simulated data, with a report.
#include <iostream>
#include <memory>

#include "ballsight/eval/demo.hpp"
#include "commands.hpp"
#include "loop_demo.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {

void add_demo_command(CLI::App& app) {
  struct Args {
    std::filesystem::path out;
    DemoOptions options;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "demo",
      "The main job on built-in simulated data: renders both camera rigs with their truth and "
      "writes DIR/report.html (and report.md)");
  cmd->add_option("--out", args->out, "Output folder (created if missing)")
      ->required()
      ->type_name("DIR");
  add_seed_option(*cmd, args->options.seed, "Scenario seed");
  cmd->add_option("--omni-frames", args->options.omni_frames, "Omni frames, 1..100")
      ->capture_default_str();
  cmd->add_option("--court-scenes", args->options.court_scenes, "Court scenes, 1..20")
      ->capture_default_str();
  cmd->add_option("--loop-balls", args->options.loop_balls,
                  "Closed loop: balls on the court, 1..60")
      ->capture_default_str();
  cmd->add_option("--loop-max-time", args->options.loop_max_time_s,
                  "Closed loop: simulated seconds per system at most")
      ->capture_default_str();
  cmd->add_flag("!--no-faults", args->options.loop_faults,
                "Closed loop: skip the run with a camera failure and restarts");
  cmd->callback([args] {
    args->options.web_dir = BALLSIGHT_WEB_DIR;
    const DemoResult result = run_demo(
        args->options, args->out, run_loop_demo,
        [](const std::string& line) { std::cout << "ballsight demo: " << line << std::endl; });
    std::cout << "ballsight demo: " << result.images_written << " images; report "
              << result.report_html.string() << "\n";
  });
}

}  // namespace ballsight::app
