#include "ballsight/service/update_planner.hpp"

#include <algorithm>

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
  // Less the balls the robot reported collected, one for each report.
  const std::vector<bool> taken = taken_by_reports(distinct, reports.collected);
  std::vector<Vec2> left;
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    if (!taken[i]) left.push_back(distinct[i]);
  }
  if (!robot) {
    update.route.planner = std::string(planner_name(options.kind));
    return update;
  }
  PlannerOptions planner = options;
  planner.previous = previous;
  update.route = plan(site_planning_problem(site, *robot, std::move(left)), planner);
  return update;
}

}  // namespace ballsight
