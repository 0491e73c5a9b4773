#pragma once
// The area of a simple polygon (shoelace formula): the simulator tests compare rendered blob areas
// with projected outlines.

#include <cmath>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight::sim::test_support {

inline double polygon_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

}  // namespace ballsight::sim::test_support
