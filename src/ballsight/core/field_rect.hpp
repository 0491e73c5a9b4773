#pragma once
// An axis-aligned rectangle on the field floor, metres: where objects may be.

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct FieldRect {
  Vec2 min_m = Vec2::Zero();
  Vec2 max_m = Vec2::Zero();

  bool contains(const Vec2& p) const {
    return p.x() >= min_m.x() && p.x() <= max_m.x() && p.y() >= min_m.y() && p.y() <= max_m.y();
  }
  bool valid() const {
    return min_m.allFinite() && max_m.allFinite() && (max_m - min_m).minCoeff() > 0.0;
  }
};

}  // namespace ballsight
