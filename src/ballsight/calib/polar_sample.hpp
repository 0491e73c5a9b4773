#pragma once
// One calibration sample of the omnivision paper (Table I): where a floor marker appears in the
// image, in polar form around the image centre, and how far from the robot it really is.

#include <optional>

namespace ballsight {

struct PolarSample {
  double theta_deg = 0.0;    // image angle around the image centre (Algorithm 2), [0, 360)
  double radius_px = 0.0;    // pixel distance from the image centre
  double distance_cm = 0.0;  // true ground distance from the robot centre
  /// True ground bearing when known, in the paper's image-angle convention: the image angle a
  /// perfectly aligned camera would see (image_theta_deg_from_robot_bearing_deg), [0, 360).
  std::optional<double> bearing_deg;
};

}  // namespace ballsight
