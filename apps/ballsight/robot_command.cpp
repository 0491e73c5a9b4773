// `ballsight robot`: the simulated collector's controller as its own program
// (robot/collector_robot.hpp). It stops when the service has seen no ball for a while (all
// collected), on SIGINT/SIGTERM, or after --max-time seconds.

#include <atomic>
#include <csignal>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/dds/dds_robot_link.hpp"
#include "ballsight/net/http_robot_link.hpp"
#include "ballsight/robot/collector_robot.hpp"
#include "commands.hpp"
#include "node_options.hpp"

namespace ballsight::app {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void stop_robot(int) {
  g_stop = true;
}

struct RobotArgs : DdsArgs {
  bool dds = false;
  std::string server = "http://127.0.0.1:8080";
  std::string token_file = "ballsight-token";
  bool long_poll = false;
  std::string summary;
  double latency_ms = 0.0;
  CollectorOptions collector;
};

/// The link the options ask for: over DDS (`participant`, made here) or HTTP.
std::unique_ptr<RobotLink> open_link(const RobotArgs& args,
                                     std::optional<dds::Participant>& participant) {
  if (args.dds) {
    validate(args);
    participant.emplace(args.domain_options());
    return std::make_unique<dds::DdsRobotLink>(*participant);
  }
  RobotLinkOptions options = RobotLinkOptions::from_url(args.server, "--server");
  const std::string token = read_file(args.token_file);  // names the file when it is missing
  options.token = token.substr(0, token.find_first_of("\r\n"));
  options.websocket = !args.long_poll;
  return std::make_unique<HttpRobotLink>(options);
}

void run_robot(RobotArgs args) {
  args.collector.latency_s = args.latency_ms / 1000.0;
  args.collector.validate();
  std::optional<dds::Participant> participant;
  const std::unique_ptr<RobotLink> link = open_link(args, participant);
  std::signal(SIGINT, stop_robot);
  std::signal(SIGTERM, stop_robot);
  const CollectorResult r = run_collector(
      *link, args.collector, g_stop,
      [](const std::string& line) { std::cout << "ballsight robot: " << line << std::endl; });
  link->stop();
  std::cout << "ballsight robot: "
            << (r.done   ? "no ball left"
                : g_stop ? "stopped"
                         : "--max-time reached")
            << " after " << r.updates << " updates; " << r.collected << " collected; " << r.stalls
            << " stalls; " << r.gaps << " updates missed, " << r.reconnects
            << " reconnects; simulated time " << r.sim_time_s << " s" << std::endl;
  if (!args.summary.empty()) {
    const nlohmann::json summary{{"done", r.done},
                                 {"updates", r.updates},
                                 {"collected", r.collected},
                                 {"gaps", r.gaps},
                                 {"reconnects", r.reconnects},
                                 {"sim_time_s", r.sim_time_s},
                                 {"seqs", r.seqs},
                                 {"latency_ms", r.latency_ms},
                                 {"stalls", r.stalls},
                                 {"dead_reckoned", r.dead_reckoned},
                                 {"guarded", r.guarded},
                                 {"recoveries", r.recoveries},
                                 {"unloads", r.unloads},
                                 {"unreachable", r.unreachable}};
    write_file_atomic(args.summary, summary.dump() + "\n");
  }
}

}  // namespace

void add_robot_command(CLI::App& app) {
  auto args = std::make_shared<RobotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "robot",
      "The simulated collector's controller: follows the navigation service's route, drives the "
      "simulated court's robot, reports the balls it collects (docs/robot-link.md)");
  CLI::Option* server =
      cmd->add_option("--server", args->server, "The navigation service, http://HOST:PORT")
          ->capture_default_str();
  CLI::Option* token =
      cmd->add_option("--token-file", args->token_file, "The service's token (its --token-file)")
          ->capture_default_str();
  cmd->add_option("--max-time", args->collector.max_time_s,
                  "Stop after this many seconds (0: when done)")
      ->capture_default_str();
  cmd->add_option("--done-after", args->collector.done_after,
                  "Stop after this many updates with no ball and no route")
      ->capture_default_str();
  cmd->add_option("--latency-ms", args->latency_ms,
                  "From the frames' capture to the wheels acting on a command: the robot steers "
                  "from where it will be then (0: from the cameras' pose)")
      ->check(CLI::Range(0.0, 5000.0))
      ->capture_default_str();
  CLI::Option* long_poll =
      cmd->add_flag("--long-poll", args->long_poll, "Long-poll instead of the WebSocket stream");
  CLI::Option* dds = cmd->add_flag(
      "--dds", args->dds,
      "Reach the court over DDS (a court-node's navigation and robot/* topics) instead of HTTP");
  dds->excludes(server)->excludes(token)->excludes(long_poll);
  for (CLI::Option* option : add_domain_options(*cmd, *args, "court's topics")) option->needs(dds);
  cmd->add_option("--summary", args->summary,
                  "Write what happened here at the end (JSON: done, updates, collected, gaps, "
                  "reconnects, sim_time_s, seqs, latency_ms per update, stalls, dead_reckoned: "
                  "frame sets driven on its own estimate out of the cameras' sight, guarded: "
                  "commands its local planner slowed, replaced or stopped, recoveries, unloads: "
                  "times it emptied its basket, unreachable: balls it gave up on)");
  cmd->callback([args] { run_robot(*args); });
}

}  // namespace ballsight::app
