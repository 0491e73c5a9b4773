#pragma once
// The robot's pose from its two colour markers (the tennis-ball-collecting-robot report, section
// 7.6: a pink ball on top at the front, a blue one at the back): each marker is fused over the
// cameras that see it, then the heading is the direction from the back marker to the front one
// and the position is the robot's reference point, placed from the markers by the known layout.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/core/raycast_box.hpp"
#include "ballsight/world/observation_fusion.hpp"

namespace ballsight {

/// The robot's body and where its markers sit, in the robot frame (x forward, reference point at
/// the origin on the floor). Defaults: the simulator's 0.60 x 0.45 x 0.30 m box with marker balls
/// of 4.5 cm radius on top, 10 cm in from its front and back faces.
struct RobotModel {
  double front_marker_x_m = 0.20;
  double back_marker_x_m = -0.20;
  double marker_height_m = 0.345;  // marker centres above the floor
  double length_m = 0.60;          // the body: a box centred on the reference point
  double width_m = 0.45;
  double height_m = 0.30;
  double marker_spacing_tolerance_m = 0.10;  // fused markers this far off the layout: not a robot

  /// Throws InputError naming the first invalid field.
  void validate() const;
  double marker_spacing_m() const { return front_marker_x_m - back_marker_x_m; }
  /// The body at `pose`, grown by `margin_m` on every side and on top.
  FloorBox body(const Pose2D& pose, double margin_m = 0.0) const {
    return {pose, Vec2(0.5 * length_m + margin_m, 0.5 * width_m + margin_m), height_m + margin_m};
  }
};

/// Pose of the reference point from the two markers' field positions.
Pose2D pose_from_markers(const Vec2& front_m, const Vec2& back_m, const RobotModel& robot);

struct RobotPoseEstimate {
  Pose2D pose;
  Vec2 front_marker_m = Vec2::Zero();
  Vec2 back_marker_m = Vec2::Zero();
  double position_sigma_m = 0.0;  // expected error of the position (rms of the two axes)
  double heading_sigma_rad = 0.0;
  std::vector<int> front_cameras;  // cameras that saw each marker
  std::vector<int> back_cameras;
};

/// The robot from the observations of its front and back markers: each marker's observations are
/// fused; of the candidate pairs whose spacing fits the layout, the one seen by the most cameras
/// (then the most precise) wins. nullopt when no pair fits.
std::optional<RobotPoseEstimate> estimate_robot_pose(
    const std::vector<FieldObservation>& front_observations,
    const std::vector<FieldObservation>& back_observations, const RobotModel& robot,
    const FusionOptions& fusion);

}  // namespace ballsight
