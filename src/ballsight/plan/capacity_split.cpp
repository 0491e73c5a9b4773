#include "ballsight/plan/capacity_split.hpp"

#include <limits>
#include <vector>

namespace ballsight {

std::vector<int> split_into_trips(const TravelModel& model, const std::vector<int>& path,
                                  const std::vector<int>& load, int capacity, int unload) {
  const int n = static_cast<int>(path.size()) - 1;  // balls path[1 .. n]
  const auto o = [&](int t) { return path[static_cast<std::size_t>(t)]; };
  // Legs and turns along the giant path: legs[t] sums o1->o2 .. o(t-1)->ot, turns[t] the turns
  // at o2 .. ot with their giant-path neighbours.
  std::vector<double> legs(static_cast<std::size_t>(n + 1), 0.0), turns(legs);
  for (int t = 2; t <= n; ++t) {
    legs[static_cast<std::size_t>(t)] =
        legs[static_cast<std::size_t>(t - 1)] + model.leg(o(t - 1), o(t));
    turns[static_cast<std::size_t>(t)] = turns[static_cast<std::size_t>(t - 1)] +
                                         (t < n ? model.turn(o(t - 1), o(t), o(t + 1)) : 0.0);
  }
  const auto trip = [&](int i, int j) {  // balls o(i) .. o(j), from the start or the unload point
    const int from = i == 1 ? 0 : unload;
    double c = (i == 1 ? model.turn(kHeading, 0, o(1)) : model.turn(o(i - 1), unload, o(i))) +
               model.leg(from, o(i)) + model.leg(o(j), unload);
    c += model.turn(from, o(i), i < j ? o(i + 1) : unload);
    if (j > i) {
      c += legs[static_cast<std::size_t>(j)] - legs[static_cast<std::size_t>(i)] +
           turns[static_cast<std::size_t>(j - 1)] - turns[static_cast<std::size_t>(i)] +
           model.turn(o(j - 1), o(j), unload);
    }
    return c;
  };
  std::vector<double> best(static_cast<std::size_t>(n + 1),
                           std::numeric_limits<double>::infinity());
  std::vector<int> start(static_cast<std::size_t>(n + 1), 1);
  best[0] = 0.0;
  for (int j = 1; j <= n; ++j) {
    int balls = 0;
    for (int i = j; i >= 1 && (balls += load[static_cast<std::size_t>(o(i))]) <= capacity; --i) {
      const double c = best[static_cast<std::size_t>(i - 1)] + trip(i, j);
      if (c < best[static_cast<std::size_t>(j)]) {
        best[static_cast<std::size_t>(j)] = c;
        start[static_cast<std::size_t>(j)] = i;
      }
    }
  }
  std::vector<bool> trip_ends(static_cast<std::size_t>(n + 1), false);
  for (int j = n; j >= 1; j = start[static_cast<std::size_t>(j)] - 1) {
    trip_ends[static_cast<std::size_t>(j)] = true;
  }
  std::vector<int> out{path[0]};
  for (int t = 1; t <= n; ++t) {
    out.push_back(o(t));
    if (trip_ends[static_cast<std::size_t>(t)]) out.push_back(unload);
  }
  return out;
}

}  // namespace ballsight
