#include "ballsight/plan/planning_problem.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "ballsight/core/enum_names.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"

namespace ballsight {
namespace {

constexpr EnumNames<PlannerKind, 4> kNames{{
    {PlannerKind::priority, "priority"},
    {PlannerKind::nearest, "nearest"},
    {PlannerKind::ballsight, "ballsight"},
    {PlannerKind::exact, "exact"},
}};

std::string point_text(const Vec2& p) {
  return fixed_pair(p.x(), p.y(), 3);
}

}  // namespace

void RobotLimits::validate() const {
  require(std::isfinite(max_speed_mps) && max_speed_mps > 0.0, "max_speed_mps", "must be positive");
  require(std::isfinite(turn_rate_dps) && turn_rate_dps > 0.0, "turn_rate_dps", "must be positive");
}

void PlanningProblem::validate() const {
  limits.validate();
  if (court) court->validate();
  require(robot.position.allFinite() && std::isfinite(robot.heading_rad), "robot pose",
          "must be finite");
  require(collector_width_m >= 0.0 && ball_radius_m > 0.0 && sweep_margin_m >= 0.0, "collector",
          "ball radius must be positive, width and margin not negative");
  require(balls.size() <= kMaxBalls, "balls",
          "at most " + std::to_string(kMaxBalls) + ", got " + std::to_string(balls.size()));
  const auto sane = [](const Vec2& p) {
    return p.allFinite() && p.cwiseAbs().maxCoeff() <= kMaxCoordinateM;
  };
  require(sane(robot.position), "robot pose", "coordinates must be finite and within 1e6 m");
  for (std::size_t i = 0; i < balls.size(); ++i) {
    require(sane(balls[i]), "balls[" + std::to_string(i) + "]",
            "coordinates must be finite and within 1e6 m");
  }
  if (court) {
    require(court->in_area(robot.position), "robot pose",
            point_text(robot.position) + " is outside the drivable area");
    require(!court->in_net_zone(robot.position), "robot pose",
            point_text(robot.position) + " is inside the net");
  }
  // Two balls closer than a radius (touching balls are two radii apart): one ball twice.
  std::vector<std::size_t> by_x(balls.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](auto a, auto b) { return balls[a].x() < balls[b].x(); });
  const double too_close = ball_radius_m;
  for (std::size_t s = 0; s < by_x.size(); ++s) {
    for (std::size_t t = s + 1;
         t < by_x.size() && balls[by_x[t]].x() - balls[by_x[s]].x() < too_close; ++t) {
      const auto [a, b] = std::minmax(by_x[s], by_x[t]);
      require((balls[a] - balls[b]).norm() >= too_close,
              "balls[" + std::to_string(a) + "] and balls[" + std::to_string(b) + "]",
              "duplicate ball at " + point_text(balls[a]));
    }
  }
  if (capacity) {
    require(capacity->balls >= 1, "capacity", "must be at least 1 ball");
    require(capacity->held >= 0 && capacity->held <= capacity->balls, "capacity",
            "holds 0 to " + std::to_string(capacity->balls) + " balls, not " +
                std::to_string(capacity->held));
    require(capacity->unload_m.allFinite(), "unload point", "must be finite");
    if (court) {
      require(court->in_area(capacity->unload_m) && !court->in_net_zone(capacity->unload_m),
              "unload point", point_text(capacity->unload_m) + " is not drivable");
    }
  }
  if (return_to) {
    require(return_to->allFinite(), "return point", "must be finite");
    if (court) {
      require(court->in_area(*return_to) && !court->in_net_zone(*return_to), "return point",
              point_text(*return_to) + " is not drivable");
    }
  }
}

double PlanningProblem::sweep_radius_m() const {
  return std::max(0.0, collector_width_m / 2.0 - ball_radius_m - sweep_margin_m);
}

std::string_view planner_name(PlannerKind kind) {
  return enum_name(kNames, kind);
}

std::optional<PlannerKind> planner_from_name(std::string_view name) {
  return enum_named(kNames, name);
}

void PlannerOptions::validate() const {
  require(std::isfinite(effort) && effort >= 0.0 && effort <= 10000.0, "effort",
          "must be in [0, 10000]");
  require(std::isfinite(target_switch_margin_s) && target_switch_margin_s >= 0.0,
          "target_switch_margin_s", "must not be negative");
  require(std::isfinite(priority.per_cm) && std::isfinite(priority.per_deg), "priority weights",
          "must be finite");
}

}  // namespace ballsight
