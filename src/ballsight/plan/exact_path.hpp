#pragma once
// The exact cheapest open path for small problems: Held-Karp dynamic programming (Held & Karp,
// "A dynamic programming approach to sequencing problems", 1962) over (visited set, last node,
// node before it), since a turn's cost depends on the two legs that meet. O(2^n n^3) time for n
// free nodes: about 7 million steps at n = 12.

#include <cassert>
#include <limits>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/plan/travel_model.hpp"

namespace ballsight {

inline constexpr int kMaxExactNodes = 12;

/// The cheapest path from node 0 through every node (ending at the last node when `fixed_end`).
/// Throws InputError when more than kMaxExactNodes nodes are free.
template <class Model>
std::vector<int> exact_path(const Model& model, bool fixed_end) {
  const int n = model.size();
  const int end = fixed_end ? n - 1 : kNone;
  const int free = n - 1 - (fixed_end ? 1 : 0);
  require(free <= kMaxExactNodes, "exact planner",
          "at most " + std::to_string(kMaxExactNodes) + " balls, got " + std::to_string(free));
  std::vector<int> path{0};
  if (free <= 0) {
    if (fixed_end) path.push_back(end);
    return path;
  }
  // Free node k is model node k + 1; `prev` slot 0 is the start, slot p + 1 free node p.
  const auto node = [](int k) { return k + 1; };
  const std::size_t sets = std::size_t{1} << free;
  const auto index = [&](std::size_t mask, int last, int prev) {
    return (mask * static_cast<std::size_t>(free) + static_cast<std::size_t>(last)) *
               static_cast<std::size_t>(free + 1) +
           static_cast<std::size_t>(prev);
  };
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(sets * static_cast<std::size_t>(free * (free + 1)), kInf);
  const auto prev_node = [&](int prev) { return prev == 0 ? 0 : node(prev - 1); };
  for (int k = 0; k < free; ++k) {
    cost[index(std::size_t{1} << k, k, 0)] =
        model.turn(kHeading, 0, node(k)) + model.leg(0, node(k));
  }
  for (std::size_t mask = 1; mask < sets; ++mask) {
    for (int last = 0; last < free; ++last) {
      if (!(mask >> last & 1U)) continue;
      for (int prev = 0; prev <= free; ++prev) {
        const double c = cost[index(mask, last, prev)];
        if (c == kInf) continue;
        for (int next = 0; next < free; ++next) {
          if (mask >> next & 1U) continue;
          const double step = model.turn(prev_node(prev), node(last), node(next)) +
                              model.leg(node(last), node(next));
          double& slot = cost[index(mask | std::size_t{1} << next, next, last + 1)];
          slot = std::min(slot, c + step);
        }
      }
    }
  }
  // Close: the last turn (towards the end, if any) and the leg to it.
  const std::size_t full = sets - 1;
  double best = kInf;
  int best_last = -1, best_prev = -1;
  for (int last = 0; last < free; ++last) {
    for (int prev = 0; prev <= free; ++prev) {
      double c = cost[index(full, last, prev)];
      if (c == kInf) continue;
      c += model.turn(prev_node(prev), node(last), end);
      if (fixed_end) c += model.leg(node(last), end);
      if (c < best) {
        best = c;
        best_last = last;
        best_prev = prev;
      }
    }
  }
  require(best < kInf, "exact planner", "no drivable order (a leg without a path)");
  // Walk back: find the state that led to (mask, last, prev).
  std::vector<int> reversed{node(best_last)};
  std::size_t mask = full;
  int last = best_last, prev = best_prev;
  while (prev != 0) {
    const std::size_t before = mask & ~(std::size_t{1} << last);
    const int p = prev - 1;
    const double target = cost[index(mask, last, prev)];
    int found = -1;
    for (int pp = 0; pp <= free && found < 0; ++pp) {
      const double c = cost[index(before, p, pp)];
      if (c == kInf) continue;
      const double step =
          model.turn(prev_node(pp), node(p), node(last)) + model.leg(node(p), node(last));
      if (std::abs(c + step - target) <= 1e-9 * std::max(1.0, std::abs(target))) found = pp;
    }
    assert(found >= 0);
    reversed.push_back(node(p));
    mask = before;
    last = p;
    prev = found;
  }
  path.insert(path.end(), reversed.rbegin(), reversed.rend());
  if (fixed_end) path.push_back(end);
  return path;
}

}  // namespace ballsight
