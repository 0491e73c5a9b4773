// `ballsight plan`: the order in which the robot collects the balls of one world model, on the
// site's court (net and fence) or, without a site, on a plane as a plain shortest-route solver.

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/pipeline/planning_input.hpp"
#include "ballsight/pipeline/route_json.hpp"
#include "ballsight/plan/planner.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "ballsight/viz/route_plot.hpp"
#include "commands.hpp"
#include "option_parsing.hpp"

namespace ballsight::app {
namespace {

struct PlanArgs {
  std::string site, world, balls_csv, robot, planner = "ballsight", cost = "time";
  std::string return_to, unload, plot;
  std::optional<int> capacity;
  double max_speed_mps = 0.0, turn_rate_dps = 0.0;  // 0: the site's (or the defaults)
  PlannerOptions options;
  bool no_sweep = false;
  bool json = false;
};

Vec2 parse_point(const std::string& text, const std::string& option) {
  const std::vector<double> xy = parse_numbers(text, 2, option, "X,Y in metres");
  return {xy[0], xy[1]};
}

PlanningProblem make_problem(const PlanArgs& args) {
  require(args.world.empty() != args.balls_csv.empty(), "--world/--balls",
          "give exactly one of --world WORLD.json or --balls CSV");
  std::vector<Vec2> balls;
  std::optional<Pose2D> robot;
  if (!args.world.empty()) {
    WorldBalls world = read_world_balls(args.world);
    balls = std::move(world.balls);
    robot = world.robot;
  } else {
    balls = read_ball_csv(args.balls_csv);
  }
  if (!args.robot.empty()) {
    const std::vector<double> r =
        parse_numbers(args.robot, 3, "--robot", "X,Y,THETA_DEG: position in metres, heading");
    robot = Pose2D{Vec2(r[0], r[1]), rad_from_deg(r[2])};
  }
  require(robot.has_value(), "--robot",
          "needed: the world model has no robot pose (give X,Y,THETA_DEG)");
  PlanningProblem problem;
  if (!args.site.empty()) {
    problem = site_planning_problem(read_site(args.site), *robot, std::move(balls));
  } else {  // a plane without a net; every point visited at its centre
    problem.robot = *robot;
    problem.balls = std::move(balls);
    problem.collector_width_m = 0.0;
  }
  if (args.max_speed_mps != 0.0) problem.limits.max_speed_mps = args.max_speed_mps;
  if (args.turn_rate_dps != 0.0) problem.limits.turn_rate_dps = args.turn_rate_dps;
  if (!args.return_to.empty()) problem.return_to = parse_point(args.return_to, "--return-to");
  require(!args.capacity || !args.unload.empty(), "--capacity", "needs --unload X,Y");
  require(args.unload.empty() || args.capacity, "--unload", "needs --capacity K");
  if (args.capacity) {
    require(*args.capacity >= 1, "--capacity",
            "must be at least 1 ball, got " + std::to_string(*args.capacity));
    problem.capacity = Capacity{*args.capacity, parse_point(args.unload, "--unload")};
  }
  return problem;
}

void print_text(const PlanningProblem& problem, const Route& route) {
  std::printf("planner %s: %zu balls, %zu out of reach\n", route.planner.c_str(),
              problem.balls.size(), route.unreachable.size());
  std::printf("route: %.2f m, %.1f s (planned in %.2f ms)\n", route.length_m, route.time_s,
              route.plan_ms);
  std::printf("order:");
  for (const int b : route.order) std::printf(" %d", b);
  std::printf("\n");
  if (!route.unreachable.empty()) {
    std::printf("out of reach:");
    for (const int b : route.unreachable) std::printf(" %d", b);
    std::printf("\n");
  }
  std::printf("waypoints (m):\n");
  for (const Vec2& w : route.waypoints_m) std::printf("  %.3f, %.3f\n", w.x(), w.y());
}

void run_plan(const PlanArgs& args) {
  PlannerOptions options = args.options;
  const std::optional<PlannerKind> kind = planner_from_name(args.planner);
  require(kind.has_value(), "--planner",
          "expected priority, nearest, ballsight or exact, got '" + args.planner + "'");
  options.kind = *kind;
  require(args.cost == "time" || args.cost == "distance", "--cost",
          "expected time or distance, got '" + args.cost + "'");
  options.cost = args.cost == "time" ? CostKind::time : CostKind::distance;
  options.sweep = !args.no_sweep;
  const PlanningProblem problem = make_problem(args);
  const Route route = plan(problem, options);
  if (!args.plot.empty()) {
    char label[96];
    std::snprintf(label, sizeof label, "%s: %.1f m, %.1f s", route.planner.c_str(), route.length_m,
                  route.time_s);
    // The standard court's floor under the site's fence: the site file gives no line layout.
    write_png_atomic(
        args.plot,
        draw_route_map(problem, court_floor(sim::TennisCourtSpec{}),
                       {{label, {200, 60, 20}, route}},
                       "ballsight plan: " + std::to_string(route.order.size()) + " balls"));
  }
  if (args.json) {
    std::cout << route_json(route).dump(2) << "\n";
  } else {
    print_text(problem, route);
  }
}

}  // namespace

void add_plan_command(CLI::App& app) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan",
      "The order in which the robot collects the balls: shortest time on the site's court (round "
      "the net, inside the fence, turning costed), or without --site a plain shortest route over "
      "points");
  cmd->add_option("--site", args->site,
                  "Site file: the court, the net and the robot (omit: a "
                  "plane without a net, points visited at their centres)");
  cmd->add_option("--world", args->world, "A world model as `court run --json` prints it");
  cmd->add_option("--balls", args->balls_csv, "Balls as CSV with the header x_m,y_m");
  cmd->add_option("--robot", args->robot,
                  "X,Y,THETA_DEG: the robot's pose (default: the world model's)");
  cmd->add_option("--planner", args->planner,
                  "priority (the report's), nearest, ballsight, "
                  "exact (n <= 12)")
      ->capture_default_str();
  cmd->add_option("--cost", args->cost, "time or distance")->capture_default_str();
  cmd->add_option("--return-to", args->return_to, "X,Y: end the route there (default: open)");
  cmd->add_option("--capacity", args->capacity, "Balls the basket holds (with --unload)");
  cmd->add_option("--unload", args->unload, "X,Y: where the basket is emptied");
  cmd->add_option("--max-speed-mps", args->max_speed_mps, "Driving speed (default: site, 1.0)");
  cmd->add_option("--turn-rate-dps", args->turn_rate_dps, "Turning rate (default: site, 90)");
  cmd->add_option("--effort", args->options.effort, "ballsight: search effort, [0, 10000]")
      ->capture_default_str();
  add_seed_option(*cmd, args->options.seed, "ballsight: seed of the search's kicks");
  cmd->add_flag("--no-sweep", args->no_sweep,
                "ballsight: visit every ball's centre instead of passing it within the collector");
  cmd->add_flag("--json", args->json,
                "JSON: {\"planner\", \"order\", \"waypoints_m\", \"length_m\", \"time_s\", "
                "\"plan_ms\", ...}");
  cmd->add_option("--plot", args->plot, "PNG of the court, the balls and the route");
  cmd->callback([args] { run_plan(*args); });
}

}  // namespace ballsight::app
