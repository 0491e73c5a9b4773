#pragma once
// The two greedy baselines. Both drive one target at a time from the robot's pose, and, as a real
// robot would, pick up on the way every ball the collector passes over (those leave the list).
//  - priority: section 7.11 of the tennis-ball report, exactly: the next target is the ball with
//    the least W1 * distance_cm + W2 * |angle_deg|, distance and angle measured in a straight line
//    from the robot's front and heading; after it the robot stands there, facing the way it came.
//  - nearest: the ball that is quickest to reach (or nearest by drivable distance), turning
//    included.

#include <vector>

#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/plan/route_geometry.hpp"

namespace ballsight {

/// The report's priority of a ball seen from `pose` (lower first).
double report_priority(const Pose2D& pose, const Vec2& ball, const PriorityWeights& weights);

std::vector<RouteStop> priority_stops(const PlanningProblem& problem, const std::vector<int>& balls,
                                      const PriorityWeights& weights);

std::vector<RouteStop> nearest_stops(const PlanningProblem& problem, const std::vector<int>& balls,
                                     CostKind cost);

}  // namespace ballsight
