#include "ballsight/core/conventions.hpp"

#include "ballsight/core/angle.hpp"

namespace ballsight {

Polar image_polar_from_pixel(const Vec2& pixel, const Vec2& image_center) {
  // dy = cy - y flips the image's downward y into an upward one.
  return polar_from_cartesian({pixel.x() - image_center.x(), image_center.y() - pixel.y()});
}

Vec2 pixel_from_image_polar(const Polar& polar_px, const Vec2& image_center) {
  const Vec2 d = cartesian_from_polar(polar_px);
  return {image_center.x() + d.x(), image_center.y() - d.y()};
}

Vec2 robot_point_from_bearing(double bearing_deg, double distance) {
  return cartesian_from_polar({bearing_deg, distance});
}

Vec2 field_point_from_image_direction(const Pose2D& robot_pose, double image_theta_deg,
                                      double distance) {
  const double field_theta_deg =
      image_theta_deg + deg_from_rad(robot_pose.heading_rad) - 90.0;  // Algorithm 6
  return robot_pose.position + cartesian_from_polar({field_theta_deg, distance});
}

}  // namespace ballsight
