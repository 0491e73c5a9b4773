#pragma once
// Angles: conversions and wrapping. Angles are radians unless the name says `_deg`.

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
