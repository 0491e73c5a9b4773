#include "ballsight/eval/plan_layouts.hpp"

#include <array>
#include <cmath>
#include <random>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/enum_names.hpp"

namespace ballsight::eval {
namespace {

constexpr EnumNames<BallLayout, 3> kNames{{
    {BallLayout::uniform, "uniform"},
    {BallLayout::practice, "practice"},
    {BallLayout::net, "net"},
}};

/// Uniform in [0, 1) from the raw generator (independent of the standard library's distributions).
double unit(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * unit(rng);
}
double normal(std::mt19937_64& rng) {
  const double u = 1.0 - unit(rng), v = unit(rng);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * kPi * v);
}

Vec2 draw_ball(BallLayout layout, std::mt19937_64& rng) {
  switch (layout) {
    case BallLayout::uniform:
      return {uniform(rng, -17.8, 17.8), uniform(rng, -8.8, 8.8)};
    case BallLayout::practice: {
      // Three in five along a baseline (just behind it), the rest at the foot of the net.
      const double y = 4.0 * normal(rng);
      if (unit(rng) < 0.6) {
        const double side = unit(rng) < 0.5 ? -1.0 : 1.0;
        return {side * (11.885 + 1.2 + 1.0 * normal(rng)), y};
      }
      const double side = unit(rng) < 0.5 ? -1.0 : 1.0;
      return {side * (0.6 + std::abs(0.8 * normal(rng))), y};
    }
    case BallLayout::net:
      return {uniform(rng, -3.0, 3.0), uniform(rng, -8.8, 8.8)};
  }
  return Vec2::Zero();
}

}  // namespace

std::string_view layout_name(BallLayout layout) {
  return enum_name(kNames, layout);
}

std::optional<BallLayout> layout_from_name(std::string_view name) {
  return enum_named(kNames, name);
}

PlanningProblem court_planning_problem(BallLayout layout, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(layout));
  PlanningProblem problem;
  problem.court = DrivableCourt::standard();
  const DrivableCourt& court = *problem.court;
  const auto fits = [&](const Vec2& p) {
    if (!court.in_area(p) || court.in_net_zone(p)) return false;
    for (const Vec2& b : problem.balls) {
      if ((b - p).norm() < 2.0 * problem.ball_radius_m) return false;
    }
    return true;
  };
  for (;;) {
    const Vec2 p(uniform(rng, -17.5, 17.5), uniform(rng, -8.5, 8.5));
    if (fits(p)) {
      problem.robot = {p, uniform(rng, -kPi, kPi)};
      break;
    }
  }
  while (static_cast<int>(problem.balls.size()) < n) {
    const Vec2 p = draw_ball(layout, rng);
    if (fits(p)) problem.balls.push_back(p);
  }
  return problem;
}

}  // namespace ballsight::eval
