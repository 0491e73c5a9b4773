#pragma once
// One-to-one pairing of two point sets, closest pairs first: a report to the ball it stands for,
// a replayed ball to the recorded one.

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct PointPair {
  std::size_t a = 0, b = 0;  // indices into the two sets
  double distance = 0.0;
};

/// Pairs of a point of `a` and one of `b` nearer than `radius`, each point in one pair at most,
/// the closest pairs taken first (ties: by index in `a`, then in `b`).
inline std::vector<PointPair> closest_pairs(const std::vector<Vec2>& a, const std::vector<Vec2>& b,
                                            double radius) {
  std::vector<PointPair> candidates;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      const double d = (a[i] - b[j]).norm();
      if (d < radius) candidates.push_back({i, j, d});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const PointPair& x, const PointPair& y) {
    return std::tie(x.distance, x.a, x.b) < std::tie(y.distance, y.a, y.b);
  });
  std::vector<bool> a_used(a.size(), false), b_used(b.size(), false);
  std::vector<PointPair> pairs;
  for (const PointPair& p : candidates) {
    if (a_used[p.a] || b_used[p.b]) continue;
    a_used[p.a] = b_used[p.b] = true;
    pairs.push_back(p);
  }
  return pairs;
}

}  // namespace ballsight
