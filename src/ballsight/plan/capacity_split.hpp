#pragma once
// A basket of K balls: the route is planned as one giant path, then cut into trips by an optimal
// split (route-first, cluster-second: Prins, Lacomme & Prodhon, "Order-first split-second methods
// for vehicle routing problems: a review", 2014): dynamic programming over where each trip ends,
// every trip closing at the unload point. O(n K).

#include <vector>

#include "ballsight/plan/travel_model.hpp"

namespace ballsight {

/// How the basket stands when the route begins.
struct Basket {
  int capacity = 1;
  int held = 0;            // balls in it now: the first trip has room for capacity - held
  bool close_last = true;  // the last trip too ends at the unload point
};

/// Cuts `path` (node 0 first, then the places with balls) into trips of at most
/// `basket.capacity` balls, `load[node]` balls picked up at each node (each at most the
/// capacity); returns the path with `unload` inserted after each trip (the last one only with
/// `close_last`), and first of all when the basket has no room for the first place's balls.
std::vector<int> split_into_trips(const TravelModel& model, const std::vector<int>& path,
                                  const std::vector<int>& load, const Basket& basket, int unload);

}  // namespace ballsight
