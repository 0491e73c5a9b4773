#pragma once
// Route planning for the ball collector: one entry point for every planner (PlannerKind).
//  - priority, nearest: the greedy baselines (greedy_planners.hpp).
//  - ballsight: the default. Minimises the route's time (or length) on the drivable court: a
//    nearest-neighbour start, 2-opt / Or-opt local search and iterated local search over
//    neighbour lists (path_search.hpp), priced with turning and the net's detours; then the
//    visits are pulled within the collector's reach of their balls (route_geometry.hpp), and with
//    a basket the path is split into trips (capacity_split.hpp). Re-planning starts from the
//    previous route and keeps its next target unless switching saves the stated margin.
//  - exact: Held-Karp (exact_path.hpp), n <= 12, over the same costs (visits at the balls).

#include "ballsight/plan/planning_problem.hpp"

namespace ballsight {

/// Plans the route; throws InputError for an invalid problem or options (what and where).
Route plan(const PlanningProblem& problem, const PlannerOptions& options);

/// ballsight's search as a plain shortest-tour solver over a symmetric cost matrix: the closed
/// tour from node 0 through every node (node 0 first, once), at `options.effort` and seed.
std::vector<int> shortest_tour(const std::vector<std::vector<double>>& cost,
                               const PlannerOptions& options);

}  // namespace ballsight
