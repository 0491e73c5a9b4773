#pragma once
// Driving a route on the court: the path from a pose to a point (the shortest drivable path, the
// turn on the spot before it and at its bends), a route's waypoints, length and time, which balls
// a leg sweeps up on the way, and "string pulling": moving each visit within the collector's
// reach of its balls so that the path runs straighter.

#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/planning_problem.hpp"

namespace ballsight {

/// A stop on a route: where the collector mouth passes and the ball it picks up (-1: unloading
/// the basket at the unload point).
struct RouteStop {
  Vec2 point_m = Vec2::Zero();
  int ball = -1;
};

/// A place the route visits: the balls it picks up there (none: the unload point), where the
/// mouth passes, and how far from `centre_m` that may be moved and still take them all.
struct Visit {
  Vec2 point_m = Vec2::Zero();
  Vec2 centre_m = Vec2::Zero();
  double reach_m = 0.0;
  std::vector<int> balls;
};

/// The stops of a list of visits: one per ball (in the visit's order), one per unload.
std::vector<RouteStop> stops_of(const std::vector<Visit>& visits);

/// Driving from `from` to `to`: the path's corners after the start (detour corners, then `to`),
/// its length, the turning on the spot (before it and at its bends) and the heading on arrival.
struct Drive {
  std::vector<Vec2> points_m;
  double length_m = 0.0;
  double turn_rad = 0.0;
  double arrive_heading_rad = 0.0;

  double time_s(const RobotLimits& limits) const;
};

Drive drive(const PlanningProblem& problem, const Pose2D& from, const Vec2& to);

/// Fills `route`'s order, targets, visits, unloads, waypoints, length and time for driving
/// `stops` from the problem's robot (and on to its return point, if any).
void measure_route(const PlanningProblem& problem, const std::vector<RouteStop>& stops,
                   Route& route);

/// Balls of `candidates` that the collector passes abeam, within the sweep radius, on the path
/// from `from` along `drive`, ordered along it, each with the point where it is passed.
std::vector<RouteStop> swept_on_the_way(const PlanningProblem& problem, const Vec2& from,
                                        const Drive& drive, const std::vector<int>& candidates);

/// Moves every visit with balls to the point within its reach of its centre (and off the net's
/// keep-out) that shortens the path through its neighbours; a few passes. The last visit of an
/// open route stays at its centre: pulled back, its balls would lie ahead of the mouth.
std::vector<Visit> pull_visits(const PlanningProblem& problem, std::vector<Visit> visits);

}  // namespace ballsight
