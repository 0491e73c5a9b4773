#pragma once
// Plain geometric value types: Vec2/Vec3, Polar, Pose2D and rigid transforms.
// Transforms are named `target_from_source`: p_in_field = field_from_robot * p_in_robot.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace ballsight {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A point in polar form: angle in degrees (counter-clockwise from +x) and radius in the
/// caller's unit (pixels for image polar coordinates, metres or cm on the ground).
struct Polar {
  double theta_deg = 0.0;
  double radius = 0.0;
};

/// Polar -> cartesian in the usual mathematical convention (x right, y up).
Vec2 cartesian_from_polar(const Polar& p);
/// Cartesian -> polar, theta in [0, 360).
Polar polar_from_cartesian(const Vec2& v);

/// A rigid transform of the plane: rotation by `theta_rad`, then translation.
struct Rigid2 {
  Vec2 translation = Vec2::Zero();
  double theta_rad = 0.0;

  static Rigid2 identity() { return {}; }
  Vec2 operator*(const Vec2& p) const;
  Rigid2 operator*(const Rigid2& other) const;
  Rigid2 inverse() const;
  Eigen::Matrix2d rotation() const;
};

/// A robot (or object) pose on the field: position and heading. The heading is the direction of
/// the robot's +x axis (forward) in the field frame. A pose *is* field_from_robot.
struct Pose2D {
  Vec2 position = Vec2::Zero();
  double heading_rad = 0.0;

  Rigid2 field_from_robot() const { return {position, heading_rad}; }
  /// The point `distance` ahead of the position along the heading (a collector's mouth).
  Vec2 ahead(double distance) const {
    return position + distance * Vec2(std::cos(heading_rad), std::sin(heading_rad));
  }
};

/// Where a robot at `pose` is after `dt` seconds at forward speed `speed` (m/s) and turn rate
/// `turn_rate` (rad/s, counter-clockwise): on the arc they describe.
Pose2D along_arc(const Pose2D& pose, double speed, double turn_rate, double dt);

/// A rigid transform of space: rotation, then translation.
struct Rigid3 {
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();

  static Rigid3 identity() { return {}; }
  Vec3 operator*(const Vec3& p) const { return rotation * p + translation; }
  Rigid3 operator*(const Rigid3& other) const;
  Rigid3 inverse() const;
  /// Rotation from an axis-angle vector (radians), as OpenCV's rvec.
  static Rigid3 from_rvec_tvec(const Vec3& rvec, const Vec3& tvec);
  Vec3 rvec() const;
};

}  // namespace ballsight
