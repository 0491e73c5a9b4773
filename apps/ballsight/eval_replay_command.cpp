// `ballsight eval replay FILE.mcap`: a recorded run's frames through this build's pipeline and
// planner, compared update by update with what was recorded (service/run_replay.hpp).

#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/service/run_replay.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

struct ReplayArgs {
  std::string file;
  std::string planner;
  bool json = false;
  bool all = false;
};

void print_summary(const nlohmann::json& r) {
  std::cout << r["file"].get<std::string>() << " (" << r["frames"].get<std::string>()
            << " frames): " << r["updates"] << " updates, " << r["replayed"] << " replayed, "
            << r["differing"] << " differ\n"
            << "  balls added " << r["balls_added"] << ", lost " << r["balls_lost"]
            << ", moved beyond 2 cm " << r["balls_moved"] << " (largest shift " << std::fixed
            << std::setprecision(4) << r["ball_shift_max_m"].get<double>() << " m)\n"
            << "  robot: largest shift " << r["robot_shift_max_m"].get<double>() << " m, turn "
            << r["robot_turn_max_deg"].get<double>() << " deg\n"
            << "  routes changed: " << r["routes_changed"] << "\n";
  for (const auto& u : r["per_update"]) {
    std::cout << "  update " << u["seq"] << ": "
              << (u.contains("not_replayed")
                      ? "not replayed, " + u["not_replayed"].get<std::string>()
                      : u.dump())
              << "\n";
  }
}

}  // namespace

void add_eval_replay_command(CLI::App& eval) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* replay = eval.add_subcommand(
      "replay",
      "Re-run a recorded run's frames through this build's pipeline and planner and compare "
      "every update with the recording: balls added, lost and moved beyond 2 cm, the robot's "
      "pose, the route (record with --record-frames png for an exact replay)");
  replay->add_option("file", args->file, "The recording (serve --record FILE.mcap)")->required();
  replay->add_option("--planner", args->planner,
                     "Plan with this planner instead of the recorded one: priority, nearest or "
                     "ballsight");
  replay->add_flag("--json", args->json, "Print JSON");
  replay->add_flag("--all", args->all, "List every update, not only those that differ");
  replay->callback([args] {
    ReplayOptions options;
    if (!args->planner.empty()) {
      options.planner = planner_from_name(args->planner);
      require(options.planner && *options.planner != PlannerKind::exact, "--planner",
              "expected priority, nearest or ballsight, got '" + args->planner + "'");
    }
    const RecordedRun run(args->file);
    const nlohmann::json result = replay_json(replay_run(run, options), args->all);
    if (args->json) {
      std::cout << result.dump(2) << "\n";
    } else {
      print_summary(result);
    }
  });
}

}  // namespace ballsight::app
