#pragma once
// The tennis-ball-collecting-robot report's world model, kept as the baseline: every detection is
// back-projected to the plane Z = Zconst "near zero" (section 2.7; the pixel undistorted first,
// as its calibration provides the distortion coefficients), balls nearer than a fixed distance are
// merged into one (section 7.8), and the robot is placed from the floor points of its front and
// back markers averaged over the cameras (section 7.6).

#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/world/robot_pose.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

struct SeedWorldOptions {
  double z_const_m = 0.0;          // section 2.7: "near to zero in our case"
  double merge_distance_m = 0.70;  // section 7.8: the collector's width
  RobotModel robot;                // marker layout, to place the reference point

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// As build_world_model, the report's way. Every merged ball is its own collection site.
WorldModel build_seed_world_model(
    const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections,
    const SeedWorldOptions& options);

}  // namespace ballsight
