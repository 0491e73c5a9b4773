#include "ballsight/plan/exact_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "ballsight/plan/path_search.hpp"
#include "ballsight/plan/travel_model.hpp"
#include "plan_fixtures.hpp"

namespace ballsight {
namespace {

TravelModel model_of(const PlanningProblem& problem, CostKind cost) {
  std::vector<Vec2> nodes{problem.robot.position};
  nodes.insert(nodes.end(), problem.balls.begin(), problem.balls.end());
  return TravelModel(nodes, problem.robot.heading_rad, problem.court, problem.limits, cost);
}

double brute_force(const TravelModel& model) {
  std::vector<int> rest(static_cast<std::size_t>(model.size() - 1));
  std::iota(rest.begin(), rest.end(), 1);
  double best = INFINITY;
  do {
    std::vector<int> path{0};
    path.insert(path.end(), rest.begin(), rest.end());
    best = std::min(best, path_cost(model, path));
  } while (std::next_permutation(rest.begin(), rest.end()));
  return best;
}

TEST(ExactPath, AgreesWithBruteForceUpToEightBalls) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const int n = 3 + static_cast<int>(seed % 6);  // 3 .. 8
    const PlanningProblem problem = test::random_court_problem(n, seed);
    for (const CostKind cost : {CostKind::time, CostKind::distance}) {
      SCOPED_TRACE(testing::Message() << "seed " << seed << " n " << n);
      const TravelModel model = model_of(problem, cost);
      const std::vector<int> path = exact_path(model, false);
      ASSERT_EQ(path.size(), static_cast<std::size_t>(n + 1));
      std::vector<int> sorted = path;
      std::sort(sorted.begin(), sorted.end());
      for (int i = 0; i <= n; ++i) EXPECT_EQ(sorted[static_cast<std::size_t>(i)], i);
      EXPECT_NEAR(path_cost(model, path), brute_force(model), 1e-9);
    }
  }
}

TEST(ExactPath, FixedEndStaysLast) {
  const PlanningProblem problem = test::random_court_problem(6, 3);
  const TravelModel model = model_of(problem, CostKind::time);
  const std::vector<int> path = exact_path(model, true);
  EXPECT_EQ(path.front(), 0);
  EXPECT_EQ(path.back(), 6);
}

TEST(PathSearch, ReachesTheExactOptimumOnSmallProblems) {
  // The heuristic at its default kick count against Held-Karp, n = 12, turns and net included.
  double worst_gap = 0.0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const PlanningProblem problem = test::random_court_problem(12, seed);
    const TravelModel model = model_of(problem, CostKind::time);
    const double optimum = path_cost(model, exact_path(model, false));
    std::vector<int> path(13);
    std::iota(path.begin(), path.end(), 0);
    PathSearchOptions options;
    options.seed = seed;
    PathSearch<TravelModel> search(model, options);
    Improvement how;
    how.kicks = 120;
    const double found = search.improve(path, how);
    EXPECT_NEAR(found, path_cost(model, path), 1e-6);
    worst_gap = std::max(worst_gap, found / optimum - 1.0);
    EXPECT_GE(found, optimum - 1e-9) << "seed " << seed;
  }
  EXPECT_LT(worst_gap, 0.02);
}

TEST(PathSearch, AnOpenPathTurnsRoundWhenItsFarEndIsNearerTheStart) {
  // Robot beyond the net's north post, balls out east and west (eval plan, seed 1, n = 8): the
  // nearest-neighbour start heads east; the optimum goes west first, the whole path reversed,
  // which joins the start to the last ball (the open end is no neighbour of anything).
  const std::vector<Vec2> nodes{{-8.287, 8.387},   {-1.321, 1.081}, {0.705, 6.390},
                                {14.123, -3.962},  {0.953, -1.965}, {-12.537, 0.148},
                                {-14.391, -0.723}, {-2.506, 4.189}, {-14.160, 2.592}};
  const TravelModel model(nodes, 0.090, DrivableCourt::standard(), RobotLimits{}, CostKind::time);
  std::vector<int> path = nearest_neighbour_path(model, model.size());
  PathSearch<TravelModel> search(model, PathSearchOptions{});
  Improvement how;
  how.kicks = 100;
  EXPECT_NEAR(search.improve(path, how), path_cost(model, exact_path(model, false)), 1e-9);
}

TEST(PathSearch, FixedEndAndFixedTargetStayAndTheCostIsTracked) {
  const PlanningProblem problem = test::random_court_problem(30, 9);
  std::vector<Vec2> nodes{problem.robot.position};
  nodes.insert(nodes.end(), problem.balls.begin(), problem.balls.end());
  nodes.push_back(Vec2(17, 8));  // a return point, node 31
  const TravelModel model(nodes, problem.robot.heading_rad, problem.court, problem.limits,
                          CostKind::time);
  PathSearchOptions options;
  options.fixed_end = true;
  PathSearch<TravelModel> search(model, options);
  std::vector<int> path(32);
  std::iota(path.begin(), path.end(), 0);
  std::swap(path[1], path[7]);  // node 7 is to stay the first target
  Improvement how;
  how.fixed_prefix = 2;
  how.kicks = 200;
  const double found = search.improve(path, how);
  EXPECT_NEAR(found, path_cost(model, path), 1e-6);
  EXPECT_EQ(path[0], 0);
  EXPECT_EQ(path[1], 7);
  EXPECT_EQ(path.back(), 31);
  std::vector<int> sorted = path;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < 32; ++i) EXPECT_EQ(sorted[static_cast<std::size_t>(i)], i);
}

}  // namespace
}  // namespace ballsight
