// `ballsight eval loop`: the closed loop per system on simulated scenes (eval/loop_eval.hpp).

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/eval/loop_eval.hpp"
#include "ballsight/net/loopback_robot_link.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct EvalLoopArgs {
  eval::LoopEvalOptions options;
  std::string systems;
  std::string layouts;
  std::string obstacles;
  double command_latency_ms = 0.0;
  std::optional<double> steer_ahead_ms;
  bool json = false;
};

std::unique_ptr<RobotLink> connect_over_loopback(CourtService& service, NavigationHub& hub) {
  return std::make_unique<LoopbackRobotLink>(service, hub);
}

void run_eval_loop(const EvalLoopArgs& args) {
  eval::LoopEvalOptions options = args.options;
  options.robot.body.command_latency_s = args.command_latency_ms / 1000.0;
  options.robot.steer_ahead_s = args.steer_ahead_ms.value_or(args.command_latency_ms) / 1000.0;
  if (!args.systems.empty()) {
    for (const CsvField& item : split_csv_fields(args.systems)) {
      options.systems.emplace_back(item.text);
    }
  }
  if (!args.layouts.empty()) {
    for (const CsvField& item : split_csv_fields(args.layouts)) {
      options.layouts.emplace_back(item.text);
    }
  }
  if (!args.obstacles.empty())
    options.obstacles = sim::parse_obstacles(args.obstacles, "--obstacles");
  const std::vector<eval::LoopRun> runs =
      eval::run_loop_eval(options, connect_over_loopback, [](const eval::LoopRun& r) {
        std::fprintf(stderr,
                     "eval loop: %-9s seed %llu, %s, %s: %d of %d balls (%d reachable) in %.1f s, "
                     "%.1f m, %d stalls, %d ticks in contact, nearest %.3f m, %d frame sets dead "
                     "reckoned, %d commands guarded, %d unloads, %d given up%s\n",
                     r.system.c_str(), static_cast<unsigned long long>(r.seed), r.layout.c_str(),
                     r.obstacles.c_str(), r.collected, r.balls, r.reachable, r.time_s, r.distance_m,
                     r.stalls, r.contacts, r.min_clearance_m, r.dead_reckoned, r.guarded, r.unloads,
                     r.unreachable,
                     r.never_overlapped ? "" : " (touched the net, the fence or an obstacle)");
      });
  const nlohmann::json j = eval::loop_eval_json(runs);
  if (args.json) {
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("%-18s %10s %12s %12s %10s\n", "system", "collected", "time_s_mean", "distance_m",
              "vs ballsight");
  for (const auto& [name, s] : j["systems"].items()) {
    std::printf(
        "%-18s %9.1f%% %12.1f %12.1f %10s\n", name.c_str(),
        100.0 * s["collected_fraction"].get<double>(), s["time_s_mean"].get<double>(),
        s["distance_m_mean"].get<double>(),
        s.contains("time_ratio_to_ballsight")
            ? (std::to_string(s["time_ratio_to_ballsight"].get<double>()).substr(0, 5) + "x")
                  .c_str()
            : "-");
  }
}

}  // namespace

void add_eval_loop_command(CLI::App& eval) {
  auto args = std::make_shared<EvalLoopArgs>();
  CLI::App* cmd = eval.add_subcommand(
      "loop",
      "The closed loop on simulated scenes, per system (report: the report's pipeline and "
      "priority planner; priority: ballsight's pipeline with that planner; ballsight): balls "
      "collected, simulated time to collect them all, distance driven, scene by scene with the "
      "balls reachable");
  add_seed_option(*cmd, args->options.seed, "Seed of the first scene (scene k: seed + k)");
  cmd->add_option("--scenes", args->options.scenes,
                  "Scenes (ball counts spread over the range; layouts in turn: uniform, clustered, "
                  "along the net, along the fence, around the net posts; the default mix of 24 "
                  "scenes of 10-120 balls takes a few hours)")
      ->capture_default_str();
  cmd->add_option("--layouts", args->layouts,
                  "Comma-separated layouts taken in turn instead of all five (uniform, clustered, "
                  "along_net, along_fence, net_posts)");
  cmd->add_option("--obstacles", args->obstacles,
                  "Obstacles on every scene: none, or a comma-separated list of person, bag and "
                  "walker (default: the mix, scene k: none, person and bag, walker for k modulo "
                  "3)");
  cmd->add_option("--record-dir", args->options.record_dir,
                  "Write each run's record of the court here (<system>-<seed>.jsonl)");
  cmd->add_flag("--record-mcap", args->options.record_mcap,
                "With --record-dir: also record each run for Foxglove (<system>-<seed>.mcap: "
                "every update, the frames of every 10th frame set; docs/recording.md)");
  cmd->add_option("--min-balls", args->options.min_balls, "Balls in the first scene")
      ->capture_default_str();
  cmd->add_option("--max-balls", args->options.max_balls, "Balls in the last scene")
      ->capture_default_str();
  cmd->add_option("--max-time", args->options.max_time_s, "Simulated seconds per run at most")
      ->capture_default_str();
  cmd->add_option("--systems", args->systems,
                  "Comma-separated subset of report,priority,ballsight");
  cmd->add_option("--command-latency-ms", args->command_latency_ms,
                  "The simulated robot's wheels act on a command this long after it was sent")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--odometry-drift", args->options.robot.body.odometry_drift,
                  "Wheel slip: the robot moves less (or more) than its wheels turn by a slowly "
                  "varying share of this standard deviation, lasting about 2 s (0.01: odometry "
                  "off by about 1 cm over a metre or two)")
      ->check(CLI::Range(0.0, 0.5))
      ->capture_default_str();
  cmd->add_option("--capacity", args->options.robot.capacity,
                  "Balls the simulated collector's basket holds (default: the site's 60); when "
                  "full it empties it at the site's unload point")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--steer-ahead-ms", args->steer_ahead_ms,
                  "The latency the robot's controller steers ahead by (default: "
                  "--command-latency-ms; 0: none, to measure what the prediction gives)")
      ->check(CLI::Range(0.0, 1000.0));
  cmd->add_flag("--json", args->json,
                "JSON: {\"systems\": {\"<name>\": {\"collected_fraction\", \"time_s_mean\", "
                "\"distance_m_mean\", \"time_ratio_to_ballsight\", \"runs\"}}, \"scenes\": "
                "[{\"seed\", \"layout\", \"obstacles\", \"balls\", \"reachable\", \"systems\"}], "
                "\"wall_clock\": {}} (simulated time only: the same every run of a seed)");
  cmd->callback([args] { run_eval_loop(*args); });
}

}  // namespace ballsight::app
