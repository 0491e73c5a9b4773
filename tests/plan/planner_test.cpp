#include "ballsight/plan/planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"
#include "plan_fixtures.hpp"

namespace ballsight {
namespace {

PlannerOptions with(PlannerKind kind, std::uint64_t seed = 1) {
  PlannerOptions options;
  options.kind = kind;
  options.seed = seed;
  return options;
}

PlannerOptions pointwise(PlannerKind kind, std::uint64_t seed = 1) {
  PlannerOptions options = with(kind, seed);
  options.sweep = false;
  return options;
}

constexpr PlannerKind kAll[] = {PlannerKind::priority, PlannerKind::nearest,
                                PlannerKind::ballsight};

/// Every reachable ball exactly once; the path never through the net nor out of the fence; each
/// visit within the collector's reach of its ball.
void expect_valid(const PlanningProblem& problem, const Route& route) {
  std::vector<int> seen = route.order;
  seen.insert(seen.end(), route.unreachable.begin(), route.unreachable.end());
  std::sort(seen.begin(), seen.end());
  ASSERT_EQ(seen.size(), problem.balls.size());
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], static_cast<int>(i));
  ASSERT_EQ(route.visits_m.size(), route.order.size());
  for (std::size_t i = 0; i < route.order.size(); ++i) {
    const Vec2& ball = problem.balls[static_cast<std::size_t>(route.order[i])];
    const double reach = problem.court && problem.court->in_net_zone(ball)
                             ? problem.court->net->clearance_m
                             : problem.sweep_radius_m();
    EXPECT_LE((route.visits_m[i] - ball).norm(), reach + 1e-9) << "visit " << i;
  }
  double length = 0.0;
  for (std::size_t i = 1; i < route.waypoints_m.size(); ++i) {
    const Vec2 &a = route.waypoints_m[i - 1], &b = route.waypoints_m[i];
    length += (b - a).norm();
    if (!problem.court) continue;
    EXPECT_FALSE(problem.court->blocked(a, b)) << "leg " << i << " crosses the net";
    EXPECT_TRUE(problem.court->in_area(b)) << "waypoint " << i;
  }
  EXPECT_NEAR(length, route.length_m, 1e-6);
}

TEST(Planner, EveryPlannerGivesAValidRoute) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    PlanningProblem problem = test::random_court_problem(static_cast<int>(10 * seed), seed);
    if (seed % 2 == 0) problem.capacity = Capacity{7, Vec2(-17, 0)};
    if (seed % 3 == 0) problem.return_to = Vec2(17, 8);
    for (const PlannerKind kind : kAll) {
      SCOPED_TRACE(testing::Message() << "seed " << seed << " " << planner_name(kind));
      const Route route = plan(problem, with(kind, seed));
      expect_valid(problem, route);
      if (problem.return_to) {
        EXPECT_EQ(route.waypoints_m.back(), *problem.return_to);
      }
      if (!problem.capacity) continue;
      // Trips of at most 7 balls, the last one unloaded too.
      ASSERT_FALSE(route.unload_after.empty());
      EXPECT_EQ(route.unload_after.back(), static_cast<int>(route.order.size()) - 1);
      int before = -1;
      for (const int u : route.unload_after) {
        EXPECT_LE(u - before, 7);
        before = u;
      }
    }
  }
}

TEST(Planner, BallsightBeatsBothBaselinesOnFiftyBalls) {
  double ours = 0.0, priority = 0.0, nearest = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const PlanningProblem problem = test::random_court_problem(50, seed);
    ours += plan(problem, with(PlannerKind::ballsight, seed)).time_s;
    priority += plan(problem, with(PlannerKind::priority)).time_s;
    nearest += plan(problem, with(PlannerKind::nearest)).time_s;
  }
  EXPECT_LT(ours, 0.85 * priority);
  EXPECT_LT(ours, 0.90 * nearest);
}

TEST(Planner, ExactIsNoWorseThanTheHeuristicWithoutSweeping) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const PlanningProblem problem = test::random_court_problem(9, seed);
    const Route exact = plan(problem, with(PlannerKind::exact));
    const Route ours = plan(problem, pointwise(PlannerKind::ballsight, seed));
    expect_valid(problem, exact);
    EXPECT_LE(exact.time_s, ours.time_s + 1e-9) << "seed " << seed;
    EXPECT_LT(ours.time_s, exact.time_s * 1.02) << "seed " << seed;
  }
}

TEST(Planner, SweepingPassesNeighbouringBallsInOneGo) {
  // Three balls 20 cm apart across the robot's way: one pass collects them all (the route ends
  // at one of them, the others are passed within the collector's reach).
  PlanningProblem problem;
  problem.robot = {Vec2(-10, 0), 0.0};
  problem.court = DrivableCourt::standard();
  problem.balls = {Vec2(-5, 0.2), Vec2(-5, 0.0), Vec2(-5, -0.2)};
  const Route swept = plan(problem, {});
  const Route each = plan(problem, pointwise(PlannerKind::ballsight));
  expect_valid(problem, swept);
  EXPECT_LT(swept.length_m, 5.25);
  EXPECT_GT(each.length_m, 5.35);
}

TEST(Planner, FactsOfTheWorldAreValidAnswers) {
  PlanningProblem problem = test::random_court_problem(0, 1);
  const Route empty = plan(problem, {});
  EXPECT_TRUE(empty.order.empty());
  EXPECT_EQ(empty.length_m, 0.0);
  problem.balls = {Vec2(3, 3), Vec2(30, 0)};  // the second beyond the fence
  const Route route = plan(problem, {});
  EXPECT_EQ(route.order, std::vector<int>{0});
  EXPECT_EQ(route.unreachable, std::vector<int>{1});
}

void expect_error(const PlanningProblem& problem, const PlannerOptions& options,
                  const std::string& fragment) {
  try {
    plan(problem, options);
    FAIL() << "no error, expected one naming " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Planner, BadInputIsNamed) {
  const PlanningProblem good = test::random_court_problem(5, 2);
  PlanningProblem p = good;
  p.balls[3].x() = NAN;
  expect_error(p, {}, "balls[3]");
  p = good;
  p.balls.push_back(p.balls[1] + Vec2(0.001, 0));
  expect_error(p, {}, "balls[1] and balls[5]");
  p = good;
  p.robot.position = Vec2(0.05, 1.0);
  expect_error(p, {}, "inside the net");
  p = good;
  p.capacity = Capacity{0, Vec2(-17, 0)};
  expect_error(p, {}, "capacity");
  PlannerOptions negative;
  negative.effort = -1;
  expect_error(good, negative, "effort");
  expect_error(test::random_court_problem(13, 1), with(PlannerKind::exact), "at most 12");
}

// A basket half full when the route begins (held), the last trip left open: the first trip has
// room for what is left, the route ends at a ball; a full basket is emptied first.
TEST(Planner, TheBasketsLoadAndAnOpenEnd) {
  PlanningProblem problem = test::random_court_problem(20, 3);
  for (const int held : {0, 5, 7}) {
    problem.capacity = Capacity{7, Vec2(-17, 0), held, false};
    for (const PlannerKind kind : {PlannerKind::ballsight, PlannerKind::priority}) {
      SCOPED_TRACE(testing::Message() << "held " << held << " " << planner_name(kind));
      const Route route = plan(problem, with(kind, 1));
      expect_valid(problem, route);
      ASSERT_FALSE(route.unload_after.empty());
      EXPECT_LT(route.unload_after.back(), static_cast<int>(route.order.size()) - 1);
      EXPECT_EQ(route.waypoints_m.back(), route.visits_m.back());
      EXPECT_LE(route.unload_after.front() + 1, 7 - held);
      if (held == 7) {
        EXPECT_EQ(route.unload_after.front(), -1);
      }
      for (std::size_t k = 1; k < route.unload_after.size(); ++k) {
        EXPECT_LE(route.unload_after[k] - route.unload_after[k - 1], 7);
      }
      // The open last trip fits the basket too.
      EXPECT_LE(static_cast<int>(route.order.size()) - 1 - route.unload_after.back(), 7);
    }
  }
  problem.capacity->held = 8;
  expect_error(problem, {}, "holds 0 to 7 balls, not 8");
}

TEST(Planner, ReplanningKeepsTheTargetAndTheOrder) {
  const PlanningProblem problem = test::random_court_problem(100, 4);
  const Route first = plan(problem, {});
  // The robot picked up the first ball; the cameras see the others again, a little noisy.
  PlanningProblem next = problem;
  next.robot = {first.visits_m[0], problem.robot.heading_rad};
  next.balls.clear();
  std::mt19937_64 rng(4);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (std::size_t i = 1; i < first.targets_m.size(); ++i) {
    next.balls.push_back(first.targets_m[i] + Vec2(noise(rng), noise(rng)));
  }
  PlannerOptions replan;
  replan.previous = &first;
  const Route again = plan(next, replan);
  expect_valid(next, again);
  EXPECT_EQ(again.order[0], 0);  // the next ball of the first route stays the target
  const Route fresh = plan(next, {});
  EXPECT_LT(again.time_s, fresh.time_s * 1.02);
}

TEST(Planner, HysteresisKeepsANearlyAsGoodTargetAndDropsAWorseOne) {
  // From the origin facing +x: A is the best first ball, B nearly as good (B-first costs a few
  // tenths of a second more), E far behind.
  PlanningProblem problem;
  const Vec2 a(3, 1), b(3, -1.2), c(6, 1), d(6, -1), e(-10, 0);
  problem.balls = {a, b, c, d, e};
  const Route fresh = plan(problem, {});
  ASSERT_EQ(fresh.order[0], 0);  // A
  Route driving;                 // the robot was sent to B first
  driving.targets_m = {b, d, c, a, e};
  PlannerOptions replan;
  replan.previous = &driving;
  EXPECT_EQ(plan(problem, replan).order[0], 1);  // B kept: switching saves less than 1 s
  replan.target_switch_margin_s = 0.01;
  EXPECT_EQ(plan(problem, replan).order[0], 0);  // a smaller margin: switch to A
  driving.targets_m = {e, a, b, c, d};
  replan.target_switch_margin_s = 1.0;
  EXPECT_EQ(plan(problem, replan).order[0], 0);  // E first costs far more than 1 s: switch
}

}  // namespace
}  // namespace ballsight
