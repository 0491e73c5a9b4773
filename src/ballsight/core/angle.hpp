#pragma once
// Angles: conversions and wrapping. Angles are radians unless the name says `_deg`.

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ballsight {

inline constexpr double kPi = std::numbers::pi;

constexpr double rad_from_deg(double deg) {
  return deg * (kPi / 180.0);
}
constexpr double deg_from_rad(double rad) {
  return rad * (180.0 / kPi);
}

/// atan2(y, x) to within 1e-5 rad (tests/core/angle_test.cpp), several times faster than the C
/// library's; for costs priced in bulk (the route planner's turns), not for geometry.
/// A minimax polynomial for atan on [0, 1] (Abramowitz & Stegun 4.4.49 form), octant reduction.
inline double fast_atan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double hi = std::max(ax, ay);
  if (hi == 0.0) return 0.0;
  const double t = std::min(ax, ay) / hi;
  const double t2 = t * t;
  double a =
      t * (0.99997726 +
           t2 * (-0.33262347 +
                 t2 * (0.19354346 + t2 * (-0.11643287 + t2 * (0.05265332 + t2 * -0.01172120)))));
  if (ay > ax) a = 0.5 * kPi - a;
  if (x < 0.0) a = kPi - a;
  return y < 0.0 ? -a : a;
}

/// Wraps to [0, 360).
inline double wrap_deg_360(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;  // fmod of -1e-17 + 360 rounds to 360
}

/// Wraps to [-180, 180).
inline double wrap_deg_180(double deg) {
  return wrap_deg_360(deg + 180.0) - 180.0;
}

/// Wraps to [-pi, pi).
inline double wrap_rad_pi(double rad) {
  return rad_from_deg(wrap_deg_180(deg_from_rad(rad)));
}

}  // namespace ballsight
