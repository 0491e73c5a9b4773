#include "ballsight/core/geometry.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"

namespace ballsight {

Vec2 cartesian_from_polar(const Polar& p) {
  const double t = rad_from_deg(p.theta_deg);
  return {p.radius * std::cos(t), p.radius * std::sin(t)};
}

Polar polar_from_cartesian(const Vec2& v) {
  return {wrap_deg_360(deg_from_rad(std::atan2(v.y(), v.x()))), v.norm()};
}

Pose2D along_arc(const Pose2D& pose, double speed, double turn_rate, double dt) {
  const double h0 = pose.heading_rad, dh = turn_rate * dt;
  Vec2 move;
  if (std::abs(dh) < 1e-9) {
    move = speed * dt * Vec2(std::cos(h0), std::sin(h0));
  } else {
    const double r = speed / turn_rate;
    move = r * Vec2(std::sin(h0 + dh) - std::sin(h0), std::cos(h0) - std::cos(h0 + dh));
  }
  return {pose.position + move, wrap_rad_pi(h0 + dh)};
}

Eigen::Matrix2d Rigid2::rotation() const {
  return Eigen::Rotation2Dd(theta_rad).toRotationMatrix();
}

Vec2 Rigid2::operator*(const Vec2& p) const {
  return rotation() * p + translation;
}

Rigid2 Rigid2::operator*(const Rigid2& other) const {
  return {rotation() * other.translation + translation, wrap_rad_pi(theta_rad + other.theta_rad)};
}

Rigid2 Rigid2::inverse() const {
  const Eigen::Matrix2d r_inv = rotation().transpose();
  return {-(r_inv * translation), wrap_rad_pi(-theta_rad)};
}

Rigid3 Rigid3::operator*(const Rigid3& other) const {
  return {rotation * other.rotation, rotation * other.translation + translation};
}

Rigid3 Rigid3::inverse() const {
  const Mat3 r_inv = rotation.transpose();
  return {r_inv, -(r_inv * translation)};
}

Rigid3 Rigid3::from_rvec_tvec(const Vec3& rvec, const Vec3& tvec) {
  const double angle = rvec.norm();
  Mat3 r = Mat3::Identity();
  if (angle > 0.0) r = Eigen::AngleAxisd(angle, rvec / angle).toRotationMatrix();
  return {r, tvec};
}

Vec3 Rigid3::rvec() const {
  const Eigen::AngleAxisd aa(rotation);
  return aa.axis() * aa.angle();
}

}  // namespace ballsight
