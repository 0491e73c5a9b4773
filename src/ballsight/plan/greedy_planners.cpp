#include "ballsight/plan/greedy_planners.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "ballsight/core/angle.hpp"

namespace ballsight {
namespace {

/// Drives to the target `choose` picks among the remaining balls, collecting what the leg sweeps
/// while the basket has room, unloading when it is full (and at the end, if the basket says so),
/// until none remain.
std::vector<RouteStop> drive_greedily(
    const PlanningProblem& problem, std::vector<int> remaining,
    const std::function<int(const Pose2D&, const std::vector<int>&)>& choose) {
  std::vector<RouteStop> stops;
  Pose2D pose = problem.robot;
  int in_basket = problem.capacity ? problem.capacity->held : 0;
  const auto go_to = [&](const Vec2& to, int ball) {
    const Drive d = drive(problem, pose, to);
    pose = {to, d.arrive_heading_rad};
    stops.push_back({to, ball});
  };
  while (!remaining.empty()) {
    if (problem.capacity && in_basket == problem.capacity->balls) {
      go_to(problem.capacity->unload_m, -1);
      in_basket = 0;
    }
    const int target = choose(pose, remaining);
    const Vec2& ball = problem.balls[static_cast<std::size_t>(target)];
    const Vec2 visit = problem.court ? problem.court->approach_point(ball) : ball;
    std::erase(remaining, target);
    std::vector<RouteStop> swept =
        swept_on_the_way(problem, pose.position, drive(problem, pose, visit), remaining);
    if (problem.capacity) {
      const int room = problem.capacity->balls - in_basket - 1;
      swept.resize(std::min(swept.size(), static_cast<std::size_t>(room)));
      in_basket += static_cast<int>(swept.size()) + 1;
    }
    for (const RouteStop& s : swept) {
      stops.push_back(s);
      std::erase(remaining, s.ball);
    }
    go_to(visit, target);
    if (problem.capacity && problem.capacity->unload_at_end && remaining.empty()) {
      go_to(problem.capacity->unload_m, -1);
    }
  }
  return stops;
}

template <class Score>
int least(const Pose2D& pose, const std::vector<int>& balls, Score score) {
  return *std::min_element(balls.begin(), balls.end(),
                           [&](int a, int b) { return score(pose, a) < score(pose, b); });
}

}  // namespace

double report_priority(const Pose2D& pose, const Vec2& ball, const PriorityWeights& weights) {
  const Vec2 d = ball - pose.position;
  const double distance_cm = 100.0 * d.norm();
  const double angle_deg = wrap_deg_180(deg_from_rad(std::atan2(d.y(), d.x()) - pose.heading_rad));
  return weights.priority(distance_cm, angle_deg);
}

std::vector<RouteStop> priority_stops(const PlanningProblem& problem, const std::vector<int>& balls,
                                      const PriorityWeights& weights) {
  return drive_greedily(problem, balls, [&](const Pose2D& pose, const std::vector<int>& left) {
    return least(pose, left, [&](const Pose2D& p, int ball) {
      return report_priority(p, problem.balls[static_cast<std::size_t>(ball)], weights);
    });
  });
}

std::vector<RouteStop> nearest_stops(const PlanningProblem& problem, const std::vector<int>& balls,
                                     CostKind cost) {
  return drive_greedily(problem, balls, [&](const Pose2D& pose, const std::vector<int>& left) {
    return least(pose, left, [&](const Pose2D& p, int ball) {
      const Vec2& b = problem.balls[static_cast<std::size_t>(ball)];
      const Drive d = drive(problem, p, problem.court ? problem.court->approach_point(b) : b);
      return cost == CostKind::time ? d.time_s(problem.limits) : d.length_m;
    });
  });
}

}  // namespace ballsight
