#pragma once
// The distance from a point to a line segment in the plane.

#include <algorithm>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// Distance from `p` to the segment a-b (to a itself when a == b).
inline double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
  return (p - (a + t * d)).norm();
}

}  // namespace ballsight
