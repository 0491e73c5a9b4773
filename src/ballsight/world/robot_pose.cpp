#include "ballsight/world/robot_pose.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void RobotModel::validate() const {
  require(std::isfinite(front_marker_x_m) && std::isfinite(back_marker_x_m) &&
              front_marker_x_m > back_marker_x_m,
          "robot model", "front_marker_x_m must be ahead of back_marker_x_m");
  require(marker_height_m >= 0.0, "robot model marker_height_m", "must be non-negative");
  require(length_m > 0.0 && width_m > 0.0 && height_m > 0.0, "robot model",
          "length_m, width_m and height_m must be positive");
  require(marker_spacing_tolerance_m > 0.0, "robot model marker_spacing_tolerance_m",
          "must be positive");
}

Pose2D pose_from_markers(const Vec2& front_m, const Vec2& back_m, const RobotModel& robot) {
  const Vec2 axis = front_m - back_m;
  Pose2D pose;
  pose.heading_rad = std::atan2(axis.y(), axis.x());
  const Vec2 middle = 0.5 * (front_m + back_m);
  const double middle_x = 0.5 * (robot.front_marker_x_m + robot.back_marker_x_m);
  pose.position = middle - middle_x * axis.normalized();
  return pose;
}

std::optional<RobotPoseEstimate> estimate_robot_pose(
    const std::vector<FieldObservation>& front_observations,
    const std::vector<FieldObservation>& back_observations, const RobotModel& robot,
    const FusionOptions& fusion) {
  robot.validate();
  const std::vector<FusedObject> fronts = fuse_observations(front_observations, fusion);
  const std::vector<FusedObject> backs = fuse_observations(back_observations, fusion);
  const FusedObject* best_front = nullptr;
  const FusedObject* best_back = nullptr;
  size_t best_support = 0;
  double best_trace = 0.0;
  for (const FusedObject& f : fronts) {
    for (const FusedObject& b : backs) {
      const double spacing = (f.position_m - b.position_m).norm();
      if (std::abs(spacing - robot.marker_spacing_m()) > robot.marker_spacing_tolerance_m) continue;
      const size_t support = f.cameras.size() + b.cameras.size();
      const double trace = f.covariance_m2.trace() + b.covariance_m2.trace();
      if (support > best_support || (support == best_support && trace < best_trace)) {
        best_front = &f, best_back = &b;
        best_support = support, best_trace = trace;
      }
    }
  }
  if (!best_front) return std::nullopt;
  RobotPoseEstimate out;
  out.front_marker_m = best_front->position_m;
  out.back_marker_m = best_back->position_m;
  out.pose = pose_from_markers(out.front_marker_m, out.back_marker_m, robot);
  out.front_cameras = best_front->cameras;
  out.back_cameras = best_back->cameras;
  // The reference point is the markers' midpoint moved along the axis: to first order its error
  // is the mean of the two markers' errors; the heading's is their difference across the axis.
  const Eigen::Matrix2d mean_cov = 0.25 * (best_front->covariance_m2 + best_back->covariance_m2);
  out.position_sigma_m = std::sqrt(0.5 * mean_cov.trace());
  const Vec2 across(-std::sin(out.pose.heading_rad), std::cos(out.pose.heading_rad));
  const double across_var =
      across.dot((best_front->covariance_m2 + best_back->covariance_m2) * across);
  out.heading_sigma_rad = std::sqrt(across_var) / robot.marker_spacing_m();
  return out;
}

}  // namespace ballsight
