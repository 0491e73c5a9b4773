#pragma once
// Random planning problems on the standard court for the plan tests.

#include <cstdint>
#include <random>

#include "ballsight/core/angle.hpp"
#include "ballsight/plan/planning_problem.hpp"

namespace ballsight::test {

/// `n` balls uniform over the fenced area (off the net), the robot at a random pose.
inline PlanningProblem random_court_problem(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(-17.5, 17.5), y(-8.5, 8.5), heading(-kPi, kPi);
  PlanningProblem problem;
  problem.court = DrivableCourt::standard();
  const auto point = [&] {
    for (;;) {
      const Vec2 p(x(rng), y(rng));
      if (!problem.court->in_net_zone(p)) return p;
    }
  };
  problem.robot = {point(), heading(rng)};
  for (int i = 0; i < n; ++i) problem.balls.push_back(point());
  return problem;
}

}  // namespace ballsight::test
