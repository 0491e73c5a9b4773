#pragma once
// A small IRIS px2cm table for tests of the table inspection and its pictures.

#include <cmath>
#include <cstdint>

#include "ballsight/camera/iris_lut.hpp"

namespace ballsight::test {

// A px2cm table whose rays rise smoothly, d = 0.02 r^2 + r cm (r in px), from `first_bin`.
inline IrisLut ramp_table(int first_bin) {
  IrisLut lut(IrisLutKind::px2cm);
  for (int theta = 0; theta < IrisLut::kDirections; ++theta) {
    for (int bin = first_bin; bin < lut.bins(); ++bin) {
      const double r = bin / 10.0;
      lut.at(theta, bin) = static_cast<std::int16_t>(std::lround(0.02 * r * r + r));
    }
  }
  return lut;
}

}  // namespace ballsight::test
