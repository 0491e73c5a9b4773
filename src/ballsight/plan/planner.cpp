#include "ballsight/plan/planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "ballsight/core/error.hpp"
#include "ballsight/plan/ball_groups.hpp"
#include "ballsight/plan/capacity_split.hpp"
#include "ballsight/plan/exact_path.hpp"
#include "ballsight/plan/greedy_planners.hpp"
#include "ballsight/plan/path_search.hpp"
#include "ballsight/plan/route_geometry.hpp"
#include "ballsight/plan/travel_model.hpp"

namespace ballsight {
namespace {

// Iterated local search kicks per ball at effort 1 (at least kMinKicks), fresh and re-planned.
// A kick priced without turns (distance cost) costs about half: five per ball there took random
// 130- and 250-point tours from 2.2 and 1.3 % above a run at effort 100 to equal (bench/plan.cpp,
// `eval plan`, `eval tsplib`: docs/route-planning.md).
constexpr double kKicksPerBall = 1.0;
constexpr double kKicksPerBallWithoutTurns = 5.0;
constexpr double kMinKicks = 100.0;
constexpr double kReplanKicksPerBall = 0.1;
// A ball of the previous route is the same ball now when it moved less than this.
constexpr double kSameBallM = 0.30;

int fresh_kicks(const PlannerOptions& options, std::size_t balls) {
  const double per_ball =
      options.cost == CostKind::time ? kKicksPerBall : kKicksPerBallWithoutTurns;
  return static_cast<int>(
      std::lround(options.effort * std::max(kMinKicks, per_ball * static_cast<double>(balls))));
}

/// The nodes the searches run on: 0 the robot, 1..k the places where groups of balls are picked
/// up (single balls unless sweeping), then the return point and the unload point if any.
struct Nodes {
  std::vector<Vec2> points;
  std::vector<BallGroup> groups;  // node i (1 <= i < balls_end) picks up groups[i - 1]
  std::vector<int> load;          // balls picked up at each node
  int balls_end = 1;
  int return_node = -1;
  int unload_node = -1;
};

Nodes make_nodes(const PlanningProblem& problem, const std::vector<int>& balls, bool group) {
  Nodes nodes;
  nodes.points.push_back(problem.robot.position);
  // Groups never reach across the net; balls against it are picked up from their side one by
  // one; a group never outgrows the basket.
  std::vector<int> side[2], at_net;
  for (const int b : balls) {
    const Vec2& p = problem.balls[static_cast<std::size_t>(b)];
    if (problem.court && problem.court->in_net_zone(p)) {
      at_net.push_back(b);
    } else {
      side[problem.court && problem.court->net && p.x() < 0.0 ? 0 : 1].push_back(b);
    }
  }
  const double radius = group ? problem.sweep_radius_m() : 0.0;
  for (const std::vector<int>& one_side : side) {
    for (BallGroup& g : group_balls(problem.balls, one_side, radius)) {
      nodes.groups.push_back(std::move(g));
    }
  }
  for (const int b : at_net) {
    nodes.groups.push_back({problem.balls[static_cast<std::size_t>(b)], 0.0, {b}});
  }
  if (problem.capacity) {
    std::vector<BallGroup> split;
    for (BallGroup& g : nodes.groups) {
      for (std::size_t k = 0; k < g.balls.size();
           k += static_cast<std::size_t>(problem.capacity->balls)) {
        const auto end =
            std::min(g.balls.size(), k + static_cast<std::size_t>(problem.capacity->balls));
        split.push_back({g.centre_m,
                         g.radius_m,
                         {g.balls.begin() + static_cast<std::ptrdiff_t>(k),
                          g.balls.begin() + static_cast<std::ptrdiff_t>(end)}});
      }
    }
    nodes.groups = std::move(split);
  }
  nodes.load.push_back(0);
  for (const BallGroup& g : nodes.groups) {
    nodes.points.push_back(problem.court ? problem.court->approach_point(g.centre_m) : g.centre_m);
    nodes.load.push_back(static_cast<int>(g.balls.size()));
  }
  nodes.balls_end = static_cast<int>(nodes.points.size());
  if (problem.return_to && !problem.capacity) {
    nodes.return_node = static_cast<int>(nodes.points.size());
    nodes.points.push_back(*problem.return_to);
    nodes.load.push_back(0);
  }
  if (problem.capacity) {
    nodes.unload_node = static_cast<int>(nodes.points.size());
    nodes.points.push_back(problem.capacity->unload_m);
    nodes.load.push_back(0);
  }
  return nodes;
}

/// The ball node nearest `target` within kSameBallM that is not `used`, or -1.
int same_ball(const TravelModel& model, const Nodes& nodes, const Vec2& target,
              const std::vector<bool>& used) {
  int best = -1;
  double best_d = kSameBallM;
  for (int i = 1; i < nodes.balls_end; ++i) {
    const double d = (model.node(i) - target).norm();
    if (!used[static_cast<std::size_t>(i)] && d < best_d) {
      best = i;
      best_d = d;
    }
  }
  return best;
}

/// The previous route's balls found again (in its order), the new ones inserted where they cost
/// least; `dirty` gets the nodes next to every change, `target` the first ball found again (the
/// one the robot is driving to), -1 if none.
std::vector<int> warm_start(const TravelModel& model, const Nodes& nodes, const Route& previous,
                            std::vector<int>& dirty, int& target) {
  std::vector<bool> used(static_cast<std::size_t>(model.size()), false);
  std::vector<int> path{0};
  for (const Vec2& ball : previous.targets_m) {
    const int best = same_ball(model, nodes, ball, used);
    if (best < 0) {
      dirty.push_back(path.back());  // a ball gone: its neighbours may do better now
      continue;
    }
    used[static_cast<std::size_t>(best)] = true;
    path.push_back(best);
  }
  target = path.size() > 1 ? path[1] : -1;
  if (nodes.return_node >= 0) path.push_back(nodes.return_node);
  const std::size_t open_end = path.size() - (nodes.return_node >= 0 ? 1 : 0);
  for (int i = 1; i < nodes.balls_end; ++i) {
    if (used[static_cast<std::size_t>(i)]) continue;
    std::size_t best_at = open_end;
    double best_cost = path.size() == open_end ? model.leg(path.back(), i)
                                               : std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < path.size(); ++k) {
      const double c =
          model.leg(path[k - 1], i) + model.leg(i, path[k]) - model.leg(path[k - 1], path[k]);
      if (c < best_cost) {
        best_cost = c;
        best_at = k;
      }
    }
    path.insert(path.begin() + static_cast<std::ptrdiff_t>(best_at), i);
    dirty.push_back(i);
  }
  if (path.size() > 1) dirty.push_back(path[1]);
  return path;
}

/// Keeps the route's next target `target` unless the free route saves more than `margin`.
void keep_target(PathSearch<TravelModel>& search, const TravelModel& model, int target,
                 double margin, std::vector<int>& path) {
  if (path.size() < 2 || path[1] == target) return;
  std::vector<int> kept = path;
  const auto at = std::find(kept.begin(), kept.end(), target);
  if (at == kept.end()) return;
  Improvement how;
  how.fixed_prefix = 2;
  how.dirty = {kept[1], *(at - 1)};  // the old first and the target's old neighbours
  if (at + 1 != kept.end()) how.dirty.push_back(*(at + 1));
  kept.erase(at);
  kept.insert(kept.begin() + 1, target);
  const double kept_cost = search.improve(kept, how);
  if (path_cost(model, path) + margin >= kept_cost) path = std::move(kept);
}

std::vector<Visit> searched_visits(const PlanningProblem& problem, const std::vector<int>& balls,
                                   const PlannerOptions& options) {
  const bool sweep = options.sweep && options.kind == PlannerKind::ballsight;
  const Nodes nodes = make_nodes(problem, balls, sweep);
  const TravelModel model(nodes.points, problem.robot.heading_rad, problem.court, problem.limits,
                          options.cost);
  std::vector<int> path;
  if (options.kind == PlannerKind::exact) {
    require(!problem.capacity, "exact planner", "plans without a basket capacity only");
    path = exact_path(model, nodes.return_node >= 0);
  } else {
    PathSearchOptions search_options;
    search_options.fixed_end = nodes.return_node >= 0;
    search_options.seed = options.seed;
    PathSearch<TravelModel> search(model, search_options);
    Improvement how;
    if (options.previous) {
      how.kicks = static_cast<int>(
          std::lround(options.effort * kReplanKicksPerBall * static_cast<double>(balls.size())));
      int target = -1;
      path = warm_start(model, nodes, *options.previous, how.dirty, target);
      search.improve(path, how);
      if (target >= 0) keep_target(search, model, target, options.target_switch_margin_s, path);
    } else {
      path = nearest_neighbour_path(model, nodes.balls_end);
      if (nodes.return_node >= 0) path.push_back(nodes.return_node);
      how.kicks = fresh_kicks(options, balls.size());
      search.improve(path, how);
    }
    if (problem.capacity) {
      const Capacity& c = *problem.capacity;
      path = split_into_trips(model, path, nodes.load, {c.balls, c.held, c.unload_at_end},
                              nodes.unload_node);
    }
  }
  std::vector<Visit> visits;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const int node = path[i];
    if (node == nodes.return_node) continue;  // measure_route drives there
    if (node == nodes.unload_node) {
      visits.push_back({model.node(node), model.node(node), 0.0, {}});
      continue;
    }
    const BallGroup& g = nodes.groups[static_cast<std::size_t>(node - 1)];
    const bool at_net = model.node(node) != g.centre_m;
    const double reach = sweep && !at_net ? problem.sweep_radius_m() - g.radius_m : 0.0;
    visits.push_back({model.node(node), model.node(node), reach, g.balls});
  }
  return visits;
}

double objective(const Route& route, CostKind cost) {
  return cost == CostKind::time ? route.time_s : route.length_m;
}

}  // namespace

Route plan(const PlanningProblem& problem, const PlannerOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  problem.validate();
  options.validate();
  Route route;
  route.planner = std::string(planner_name(options.kind));
  std::vector<int> reachable;
  for (int i = 0; i < static_cast<int>(problem.balls.size()); ++i) {
    const bool in_reach =
        !problem.court || problem.court->in_area(problem.balls[static_cast<std::size_t>(i)]);
    (in_reach ? reachable : route.unreachable).push_back(i);
  }
  switch (options.kind) {
    case PlannerKind::priority:
      measure_route(problem, priority_stops(problem, reachable, options.priority), route);
      break;
    case PlannerKind::nearest:
      measure_route(problem, nearest_stops(problem, reachable, options.cost), route);
      break;
    case PlannerKind::ballsight:
    case PlannerKind::exact: {
      const std::vector<Visit> visits = searched_visits(problem, reachable, options);
      measure_route(problem, stops_of(visits), route);
      if (options.kind == PlannerKind::ballsight && options.sweep) {
        Route pulled = route;
        measure_route(problem, stops_of(pull_visits(problem, visits)), pulled);
        if (objective(pulled, options.cost) < objective(route, options.cost)) {
          route = std::move(pulled);
        }
      }
      break;
    }
  }
  route.plan_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return route;
}

std::vector<int> shortest_tour(const std::vector<std::vector<double>>& cost,
                               const PlannerOptions& options) {
  options.validate();
  const std::size_t n = cost.size();
  if (n < 2) return n == 1 ? std::vector<int>{0} : std::vector<int>{};
  // The return to node 0 is a copy of it as the path's fixed end.
  std::vector<std::vector<double>> with_end = cost;
  for (std::size_t i = 0; i < n; ++i) with_end[i].push_back(cost[i][0]);
  with_end.push_back(with_end[0]);
  with_end[n][n] = 0.0;
  const MatrixModel model(std::move(with_end));
  PathSearchOptions search_options;
  search_options.fixed_end = true;
  search_options.seed = options.seed;
  PathSearch<MatrixModel> search(model, search_options);
  std::vector<int> path = nearest_neighbour_path(model, static_cast<int>(n));
  path.push_back(static_cast<int>(n));
  Improvement how;
  PlannerOptions without_turns = options;
  without_turns.cost = CostKind::distance;
  how.kicks = fresh_kicks(without_turns, n - 1);
  search.improve(path, how);
  path.pop_back();
  return path;
}

}  // namespace ballsight
