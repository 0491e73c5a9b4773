#include "ballsight/plan/capacity_split.hpp"

#include <limits>
#include <vector>

namespace ballsight {

std::vector<int> split_into_trips(const TravelModel& model, const std::vector<int>& path,
                                  const std::vector<int>& load, const Basket& basket, int unload) {
  const int n = static_cast<int>(path.size()) - 1;  // balls path[1 .. n]
  const auto o = [&](int t) { return path[static_cast<std::size_t>(t)]; };
  const auto at = [](std::vector<double>& v, int t) -> double& {
    return v[static_cast<std::size_t>(t)];
  };
  // A basket without room for the first place's balls is emptied first: every trip then starts at
  // the unload point (the drive there is the same for every split).
  const bool unload_first =
      n > 0 && load[static_cast<std::size_t>(o(1))] > basket.capacity - basket.held;
  const int first_room = unload_first ? basket.capacity : basket.capacity - basket.held;
  // Legs and turns along the giant path: legs[t] sums o1->o2 .. o(t-1)->ot, turns[t] the turns
  // at o2 .. ot with their giant-path neighbours.
  std::vector<double> legs(static_cast<std::size_t>(n + 1), 0.0), turns(legs);
  for (int t = 2; t <= n; ++t) {
    at(legs, t) = at(legs, t - 1) + model.leg(o(t - 1), o(t));
    at(turns, t) = at(turns, t - 1) + (t < n ? model.turn(o(t - 1), o(t), o(t + 1)) : 0.0);
  }
  const auto trip = [&](int i, int j) {  // balls o(i) .. o(j), from the start or the unload point
    const bool from_start = i == 1 && !unload_first;
    const bool closes = j < n || basket.close_last;
    const int from = from_start ? 0 : unload;
    double c = from_start ? model.turn(kHeading, 0, o(1))
                          : model.turn(i == 1 ? 0 : o(i - 1), unload, o(i));
    c += model.leg(from, o(i)) + (closes ? model.leg(o(j), unload) : 0.0);
    if (i < j || closes) c += model.turn(from, o(i), i < j ? o(i + 1) : unload);
    if (j > i) {
      c += at(legs, j) - at(legs, i) + at(turns, j - 1) - at(turns, i) +
           (closes ? model.turn(o(j - 1), o(j), unload) : 0.0);
    }
    return c;
  };
  std::vector<double> best(static_cast<std::size_t>(n + 1),
                           std::numeric_limits<double>::infinity());
  std::vector<int> start(static_cast<std::size_t>(n + 1), 1);
  best[0] = 0.0;
  for (int j = 1; j <= n; ++j) {
    int balls = 0;
    for (int i = j; i >= 1; --i) {
      balls += load[static_cast<std::size_t>(o(i))];
      if (balls > (i == 1 ? first_room : basket.capacity)) break;
      const double c = at(best, i - 1) + trip(i, j);
      if (c < at(best, j)) {
        at(best, j) = c;
        start[static_cast<std::size_t>(j)] = i;
      }
    }
  }
  std::vector<bool> trip_ends(static_cast<std::size_t>(n + 1), false);
  for (int j = n; j >= 1; j = start[static_cast<std::size_t>(j)] - 1) {
    trip_ends[static_cast<std::size_t>(j)] = j < n || basket.close_last;
  }
  std::vector<int> out{path[0]};
  if (unload_first) out.push_back(unload);
  for (int t = 1; t <= n; ++t) {
    out.push_back(o(t));
    if (trip_ends[static_cast<std::size_t>(t)]) out.push_back(unload);
  }
  return out;
}

}  // namespace ballsight
