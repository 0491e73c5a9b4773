#pragma once
// The omnivision paper's coordinate conventions, written once (see docs/conventions.md).
//
// Image: pixel (x, y) with x to the right and y *down*; the image polar angle is measured around
// an image centre (cx, cy) counter-clockwise as seen on screen, 0 deg pointing right, 90 deg up.
// Robot-local frame: x forward, y to the left, z up (REP 103); ground points in metres.
// Field frame: x, y on the floor, z up; a robot pose is field_from_robot.

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// Algorithm 2 of the omnivision paper: dx = x - cx, dy = cy - y, theta = atan2(dy, dx) in
/// [0, 360), r = hypot(dx, dy) in pixels.
Polar image_polar_from_pixel(const Vec2& pixel, const Vec2& image_center);

/// Inverse of image_polar_from_pixel.
Vec2 pixel_from_image_polar(const Polar& polar_px, const Vec2& image_center);

/// The paper's direction convention: image angle 90 deg (up in the image) is the robot's forward
/// direction, so robot bearing = image angle - 90 deg (Algorithm 6 with robot heading 0).
inline double robot_bearing_deg_from_image_theta_deg(double image_theta_deg) {
  return image_theta_deg - 90.0;
}
inline double image_theta_deg_from_robot_bearing_deg(double bearing_deg) {
  return bearing_deg + 90.0;
}

/// A ground point in the robot frame from its bearing (deg, counter-clockwise from forward) and
/// ground distance.
Vec2 robot_point_from_bearing(double bearing_deg, double distance);

/// Algorithm 6 of the omnivision paper: a point seen at image angle `image_theta_deg` and ground
/// distance `distance` from a robot at `robot_pose` lands at
/// robot + distance * (cos, sin)(image_theta + heading - 90 deg) in the field frame.
Vec2 field_point_from_image_direction(const Pose2D& robot_pose, double image_theta_deg,
                                      double distance);

/// Robot-local <-> field for ground points.
inline Vec2 field_from_robot_point(const Pose2D& robot_pose, const Vec2& p_in_robot) {
  return robot_pose.field_from_robot() * p_in_robot;
}
inline Vec2 robot_from_field_point(const Pose2D& robot_pose, const Vec2& p_in_field) {
  return robot_pose.field_from_robot().inverse() * p_in_field;
}

}  // namespace ballsight
