// Route planning speed on one core: the report's priority rule and ballsight's planner (fresh, and
// re-planned after the robot collected one ball), uniform balls over the fenced court with the
// net, time cost. Targets (issue: route planning): ballsight 100 balls <= 5 ms, 400 balls <= 100
// ms, re-plan of 100 balls <= 1 ms. Run: build/bin/bench_plan

#include <benchmark/benchmark.h>

#include "ballsight/eval/plan_layouts.hpp"
#include "ballsight/plan/planner.hpp"

namespace {

using namespace ballsight;

PlanningProblem problem_of(benchmark::State& state) {
  return eval::court_planning_problem(eval::BallLayout::uniform, static_cast<int>(state.range(0)),
                                      1);
}

void plan_benchmark(benchmark::State& state, PlannerKind kind) {
  const PlanningProblem problem = problem_of(state);
  PlannerOptions options;
  options.kind = kind;
  for (auto _ : state) benchmark::DoNotOptimize(plan(problem, options));
  state.SetItemsProcessed(state.iterations());
}

void BM_PlanPriority(benchmark::State& state) {
  plan_benchmark(state, PlannerKind::priority);
}
void BM_PlanNearest(benchmark::State& state) {
  plan_benchmark(state, PlannerKind::nearest);
}
void BM_PlanBallsight(benchmark::State& state) {
  plan_benchmark(state, PlannerKind::ballsight);
}

void BM_ReplanBallsightAfterCollect(benchmark::State& state) {
  const PlanningProblem problem = problem_of(state);
  const Route first = plan(problem, {});
  PlanningProblem next = problem;
  next.robot = {first.visits_m[0], problem.robot.heading_rad};
  next.balls.erase(next.balls.begin() + first.order[0]);
  PlannerOptions options;
  options.previous = &first;
  for (auto _ : state) benchmark::DoNotOptimize(plan(next, options));
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_PlanPriority)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanNearest)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanBallsight)->Arg(20)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReplanBallsightAfterCollect)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
