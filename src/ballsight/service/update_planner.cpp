#include "ballsight/service/update_planner.hpp"

#include <algorithm>

#include "ballsight/core/error.hpp"
#include "ballsight/pipeline/planning_input.hpp"
#include "ballsight/plan/planner.hpp"

namespace ballsight {

NavigationUpdate plan_update(const Site& site, const WorldModel& world,
                             const ClientReports& reports, const Route* previous,
                             const PlannerOptions& options) {
  const std::int64_t capture_ns = world.capture_time_ns;
  NavigationUpdate update;
  update.capture_time_ns = capture_ns;
  update.world = world;
  std::optional<Pose2D> robot;
  std::int64_t robot_ns = 0;
  if (world.robot) {
    robot = world.robot->pose;
    robot_ns = capture_ns;
  }
  if (reports.robot && reports.robot->set_ns > robot_ns) robot = reports.robot->value;
  std::vector<Vec2> balls;
  for (const FusedBall& b : world.balls) balls.push_back(b.position_m);
  if (reports.balls && reports.balls->set_ns > capture_ns) balls = reports.balls->value;
  // Two detections closer than a ball's radius would be one ball twice: keep the first.
  std::vector<Vec2> distinct;
  for (const Vec2& b : balls) {
    if (std::none_of(distinct.begin(), distinct.end(),
                     [&](const Vec2& d) { return (d - b).norm() < site.ball_radius_m; })) {
      distinct.push_back(b);
    }
  }
  // Less the balls the robot reported collected, one for each report, and those it gave up on.
  const std::vector<bool> taken = taken_by_reports(distinct, reports.collected);
  update.reports = reports;
  const auto given_up = [&](const Vec2& b) {
    return std::any_of(
        reports.unreachable.begin(), reports.unreachable.end(),
        [&](const UnreachableMark& m) { return (m.position_m - b).norm() < kCollectedMatchM; });
  };
  std::vector<Vec2> left;
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    if (!taken[i] && !given_up(distinct[i])) left.push_back(distinct[i]);
  }
  if (!robot) {
    update.route.planner = std::string(planner_name(options.kind));
    return update;
  }
  PlannerOptions planner = options;
  planner.previous = previous;
  PlanningProblem problem = site_planning_problem(site, *robot, std::move(left));
  // Round what stands on the court.
  problem.court =
      with_obstacles(*problem.court, obstacle_discs(world, *robot), obstacle_keep_m(site.robot));
  // The basket matters when the balls left outnumber its room: then the route plans its unload
  // trips, the last one left open (the collection ends at the last ball).
  const int capacity = site.robot.capacity;
  const int held = std::clamp(reports.basket ? reports.basket->value : 0, 0, capacity);
  if (static_cast<int>(problem.balls.size()) > capacity - held) {
    problem.capacity = Capacity{capacity, site.unload_point(), held, false};
  }
  update.route = plan(problem, planner);
  return update;
}

NavigationUpdate publishable_update(const Site& site, const WorldModel& world,
                                    const ClientReports& reports, const Route* previous,
                                    const PlannerOptions& options, std::string& error) {
  error.clear();
  try {
    return plan_update(site, world, reports, previous, options);
  } catch (const InputError& e) {
    error = e.what();
    NavigationUpdate update;
    update.capture_time_ns = world.capture_time_ns;
    update.world = world;
    update.reports = reports;
    return update;
  }
}

}  // namespace ballsight
