#include "ballsight/plan/route_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/plan/travel_model.hpp"

namespace ballsight {
namespace {

/// Closest point to p on segment a-b and its parameter in [0, 1].
std::pair<Vec2, double> closest_on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return {a + t * d, t};
}

/// The net stands between a and b (each on its own side, level with the net's keep-out).
bool across_the_net(const PlanningProblem& problem, const Vec2& a, const Vec2& b) {
  if (!problem.court || !problem.court->net) return false;
  const CourtNet& net = *problem.court->net;
  const double y_end = net.end_m();
  return (a.x() >= 0.0) != (b.x() >= 0.0) && std::abs(b.y()) < y_end && std::abs(a.y()) < y_end;
}

bool drivable(const PlanningProblem& problem, const Vec2& p) {
  return !problem.court || (problem.court->in_area(p) && !problem.court->in_net_zone(p));
}

}  // namespace

double Drive::time_s(const RobotLimits& limits) const {
  return length_m / limits.max_speed_mps + turn_rad / rad_from_deg(limits.turn_rate_dps);
}

Drive drive(const PlanningProblem& problem, const Pose2D& from, const Vec2& to) {
  Drive d;
  if (problem.court) {
    const DrivablePath path = shortest_path(*problem.court, from.position, to);
    d.points_m = path.via;
  }
  d.points_m.push_back(to);
  double heading = from.heading_rad;
  Vec2 at = from.position;
  for (const Vec2& p : d.points_m) {
    const Vec2 step = p - at;
    const double length = step.norm();
    if (length > 0.0) {
      const double direction = std::atan2(step.y(), step.x());
      d.turn_rad += TravelModel::turn_angle_rad(heading, direction);
      heading = direction;
    }
    d.length_m += length;
    at = p;
  }
  d.arrive_heading_rad = heading;
  return d;
}

void measure_route(const PlanningProblem& problem, const std::vector<RouteStop>& stops,
                   Route& route) {
  route.order.clear();
  route.targets_m.clear();
  route.visits_m.clear();
  route.unload_after.clear();
  route.unload_m.reset();
  if (problem.capacity) route.unload_m = problem.capacity->unload_m;
  route.waypoints_m = {problem.robot.position};
  route.length_m = 0.0;
  route.time_s = 0.0;
  Pose2D pose = problem.robot;
  const auto go = [&](const Vec2& to) {
    const Drive d = drive(problem, pose, to);
    route.waypoints_m.insert(route.waypoints_m.end(), d.points_m.begin(), d.points_m.end());
    route.length_m += d.length_m;
    route.time_s += d.time_s(problem.limits);
    pose = {to, d.arrive_heading_rad};
  };
  for (const RouteStop& stop : stops) {
    go(stop.point_m);
    if (stop.ball < 0) {
      route.unload_after.push_back(static_cast<int>(route.order.size()) - 1);
      continue;
    }
    route.order.push_back(stop.ball);
    route.targets_m.push_back(problem.balls[static_cast<std::size_t>(stop.ball)]);
    route.visits_m.push_back(stop.point_m);
  }
  if (problem.return_to) go(*problem.return_to);
}

std::vector<RouteStop> swept_on_the_way(const PlanningProblem& problem, const Vec2& from,
                                        const Drive& drive, const std::vector<int>& candidates) {
  const double r = problem.sweep_radius_m();
  std::vector<std::pair<double, RouteStop>> swept;
  for (const int ball : candidates) {
    const Vec2& b = problem.balls[static_cast<std::size_t>(ball)];
    Vec2 a = from;
    double along = 0.0;
    for (const Vec2& p : drive.points_m) {
      const auto [q, t] = closest_on_segment(a, p, b);
      // Passed abeam, inside the mouth, and not with the net between.
      if (t > 0.0 && t < 1.0 && (q - b).norm() <= r && !across_the_net(problem, q, b)) {
        swept.push_back({along + t * (p - a).norm(), {q, ball}});
        break;
      }
      along += (p - a).norm();
      a = p;
    }
  }
  std::stable_sort(swept.begin(), swept.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<RouteStop> out;
  for (const auto& s : swept) out.push_back(s.second);
  return out;
}

std::vector<RouteStop> stops_of(const std::vector<Visit>& visits) {
  std::vector<RouteStop> stops;
  for (const Visit& v : visits) {
    if (v.balls.empty()) stops.push_back({v.point_m, -1});
    for (const int b : v.balls) stops.push_back({v.point_m, b});
  }
  return stops;
}

std::vector<Visit> pull_visits(const PlanningProblem& problem, std::vector<Visit> visits) {
  constexpr int kPasses = 4;
  for (int pass = 0; pass < kPasses; ++pass) {
    for (std::size_t i = 0; i < visits.size(); ++i) {
      Visit& v = visits[i];
      if (v.balls.empty() || v.reach_m <= 0.0) continue;
      // Along the fence the mouth comes square to it, at the approach point.
      if (problem.court && problem.court->in_fence_lane(v.centre_m)) continue;
      // The neighbouring points the path runs between: the previous visit (or the start) and the
      // next visit (or the return point), or the detour corners between.
      std::optional<Vec2> next;
      if (i + 1 < visits.size()) {
        next = visits[i + 1].point_m;
      } else if (problem.return_to) {
        next = *problem.return_to;
      } else {
        continue;  // the last visit of an open route
      }
      const Vec2 prev = i == 0 ? problem.robot.position : visits[i - 1].point_m;
      const Drive in = drive(problem, {prev, 0.0}, v.point_m);
      const Vec2 a = in.points_m.size() > 1 ? in.points_m[in.points_m.size() - 2] : prev;
      const Vec2 c = drive(problem, {v.point_m, 0.0}, *next).points_m.front();
      const Vec2 q = closest_on_segment(a, c, v.centre_m).first;
      const double off = (q - v.centre_m).norm();
      Vec2 target = off <= v.reach_m ? q : v.centre_m + (q - v.centre_m) * (v.reach_m / off);
      // In the net's lane the robot drives in and backs out: from the lane's edge if it reaches.
      if (problem.court && problem.court->in_net_lane(target)) {
        const Vec2 edge(std::copysign(problem.court->net->travel_clearance_m, v.centre_m.x()),
                        target.y());
        if ((edge - v.centre_m).norm() <= v.reach_m) target = edge;
      }
      if (drivable(problem, target)) v.point_m = target;
    }
  }
  return visits;
}

}  // namespace ballsight
