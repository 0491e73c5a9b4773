// `ballsight robot`: the simulated collector's controller, its own program. It knows only what
// the navigation service sends (its pose as the cameras saw it, the route), over RobotLink: it
// follows the route's waypoints with its collector's mouth (plan/path_follower.hpp), sends its
// wheels' command for every update to the simulated court (PUT /api/v1/sim/drive), acknowledges
// the update and reports the balls its collector took. It stops when the service has seen no
// ball for a while (all collected), on SIGINT/SIGTERM, or after --max-time seconds.

#include <atomic>
#include <cmath>
#include <csignal>
#include <iostream>
#include <memory>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/net/robot_link.hpp"
#include "ballsight/plan/path_follower.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void stop_robot(int) {
  g_stop = true;
}

struct RobotArgs {
  std::string server = "http://127.0.0.1:8080";
  std::string token_file = "ballsight-token";
  double max_time_s = 0.0;  // 0: until done or a signal
  bool long_poll = false;
  int done_after = 10;  // updates with no ball seen and no route: all collected
};

void run_robot(const RobotArgs& args) {
  require(args.max_time_s >= 0.0, "--max-time", "must not be negative");
  require(args.done_after >= 1, "--done-after", "must be at least 1");
  RobotLinkOptions options = RobotLinkOptions::from_url(args.server, "--server");
  std::string token = read_file(args.token_file);  // throws naming the file when it is missing
  options.token = token.substr(0, token.find_first_of("\r\n"));
  options.websocket = !args.long_poll;
  std::signal(SIGINT, stop_robot);
  std::signal(SIGTERM, stop_robot);
  const FollowerOptions follow;  // the site's defaults: mouth 0.30 m ahead, 1 m/s, 90 deg/s
  PathFollower follower(follow);
  RobotLink link(options);
  const auto started = std::chrono::steady_clock::now();
  int empty = 0, updates = 0, collected = 0;
  std::vector<Vec2> planned;  // the route's waypoints being followed
  while (!g_stop) {
    if (args.max_time_s > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
            args.max_time_s) {
      std::cout << "ballsight robot: --max-time reached" << std::endl;
      break;
    }
    const std::optional<LinkUpdate> u = link.next(std::chrono::milliseconds(500));
    if (!u) continue;
    ++updates;
    FollowCommand command;
    if (u->robot) {
      if (u->waypoints_m != planned) {
        planned = u->waypoints_m;
        follower.set_path(planned);
      }
      command = follower.command(*u->robot);
    }
    const std::optional<nlohmann::json> drove =
        link.call("PUT", "/api/v1/sim/drive",
                  {{"seq", u->seq},
                   {"speed_mps", command.speed_mps},
                   {"turn_rate_dps", deg_from_rad(command.turn_rate_rps)}});
    link.acknowledge(u->seq);
    const int taken = drove ? drove->value("collected", 0) : 0;
    if (taken > 0 && u->robot) {
      // The collector's sensor counts balls; they were at its mouth.
      const Pose2D& p = *u->robot;
      const Vec2 mouth = p.position + follow.mouth_ahead_m *
                                          Vec2(std::cos(p.heading_rad), std::sin(p.heading_rad));
      link.report_collected(std::vector<Vec2>(static_cast<std::size_t>(taken), mouth));
      collected += taken;
    }
    if (updates % 100 == 0) {
      std::cout << "ballsight robot: update " << u->seq << ", " << u->balls_m.size()
                << " balls seen, " << collected << " collected"
                << (drove ? ", simulated time " + std::to_string(drove->value("time_s", 0.0)) + " s"
                          : "")
                << std::endl;
    }
    empty = u->balls_m.empty() && u->visits_m.empty() ? empty + 1 : 0;
    if (empty >= args.done_after) {
      std::cout << "ballsight robot: no ball left after " << updates << " updates; " << collected
                << " collected; " << link.status().gaps << " updates missed, "
                << link.status().reconnects << " reconnects" << std::endl;
      break;
    }
  }
  link.stop();
}

}  // namespace

void add_robot_command(CLI::App& app) {
  auto args = std::make_shared<RobotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "robot",
      "The simulated collector's controller: follows the navigation service's route, drives the "
      "simulated court's robot, reports the balls it collects (docs/robot-link.md)");
  cmd->add_option("--server", args->server, "The navigation service, http://HOST:PORT")
      ->capture_default_str();
  cmd->add_option("--token-file", args->token_file, "The service's token (its --token-file)")
      ->capture_default_str();
  cmd->add_option("--max-time", args->max_time_s, "Stop after this many seconds (0: when done)")
      ->capture_default_str();
  cmd->add_option("--done-after", args->done_after,
                  "Stop after this many updates with no ball and no route")
      ->capture_default_str();
  cmd->add_flag("--long-poll", args->long_poll, "Long-poll instead of the WebSocket stream");
  cmd->callback([args] { run_robot(*args); });
}

}  // namespace ballsight::app
