#pragma once
// What the route planner is given on a real site: the drivable court from the site file, the
// balls from a world model (`court run --json`) or a CSV file, and the robot's collector mouth
// placed from the robot's pose.

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/obstacle_detours.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/world/site.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

/// The world model's obstacles as the planner sees them from `robot`: the circle round each
/// footprint, the 16 nearest the robot, less one centred on its body (its own, when the cameras
/// missed its markers).
std::vector<ObstacleDisc> obstacle_discs(const WorldModel& world, const Pose2D& robot);
/// How far the robot's reference point keeps from an obstacle's circle: half the diagonal of its
/// body with the site's collector (the box of 0.60 x 0.45 m), and 10 cm.
double obstacle_keep_m(const SiteRobot& robot);

/// A problem on the site: its court, the robot's limits and collector; `robot` is the pose of the
/// robot's reference point (the collector mouth is `robot.collector_x_m` ahead of it). A ball
/// seen up to 25 cm beyond the fence (the cameras' error far from them) is placed against it,
/// inside; one farther out stays where it was seen (the route lists it as unreachable).
PlanningProblem site_planning_problem(const Site& site, const Pose2D& robot,
                                      std::vector<Vec2> balls);

/// One frame set's world model as `court run --json` prints it.
struct WorldBalls {
  std::vector<Vec2> balls;
  std::optional<Pose2D> robot;  // null when the cameras did not see it
};

/// Parses a world model's JSON; `source` names it in messages ("<source>: balls[2].x_m: ...").
WorldBalls parse_world_balls(std::string_view text, const std::string& source);
WorldBalls read_world_balls(const std::filesystem::path& file);

/// Balls from CSV text with the header `x_m,y_m`, one ball a line ("<source>:<line>:<column>:
/// ..." for a bad value).
std::vector<Vec2> parse_ball_csv(std::string_view text, const std::string& source);
std::vector<Vec2> read_ball_csv(const std::filesystem::path& file);

}  // namespace ballsight
