#pragma once
// Algorithm 2 of the omnivision paper: clicked marker pixels and the markers' true positions
// become polar calibration samples around an image centre.

#include <span>
#include <string>
#include <vector>

#include "ballsight/calib/polar_sample.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// A floor marker: where it was clicked in the image and where it lies in the robot frame (m).
struct MarkerObservation {
  Vec2 pixel = Vec2::Zero();
  Vec2 p_in_robot = Vec2::Zero();
};

/// A floor marker with its position in the field frame (m).
struct FieldMarkerObservation {
  Vec2 pixel = Vec2::Zero();
  Vec2 p_in_field = Vec2::Zero();
};

/// One sample: theta/radius of the pixel around `image_center` (Algorithm 2), the marker's
/// ground distance in cm and its true bearing in the paper's image-angle convention.
/// Throws InputError naming `where` when the pixel or position is not finite, or the marker sits
/// on the image centre or under the robot centre.
PolarSample sample_from_marker(const MarkerObservation& marker, const Vec2& image_center,
                               const std::string& where = "marker");

/// All markers; errors name the marker's index.
std::vector<PolarSample> samples_from_markers(std::span<const MarkerObservation> markers,
                                              const Vec2& image_center);

/// Markers placed in the field frame, seen by a robot at `robot_pose` (field_from_robot).
std::vector<PolarSample> samples_from_field_markers(std::span<const FieldMarkerObservation> markers,
                                                    const Pose2D& robot_pose,
                                                    const Vec2& image_center);

}  // namespace ballsight
