#include "ballsight/sim/court_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

SceneSphere marker(const RobotBox& robot, ObjectKind kind, double forward_m, const cv::Vec3b& bgr) {
  const Vec2 p = robot.pose.field_from_robot() * Vec2(forward_m, 0.0);
  return {kind, 0, Vec3(p.x(), p.y(), robot.height_m + robot.marker_radius_m),
          robot.marker_radius_m, bgr};
}

}  // namespace

std::string_view object_kind_name(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::tennis_ball:
      return "tennis_ball";
    case ObjectKind::reference_ball:
      return "reference_ball";
    case ObjectKind::robot_front_marker:
      return "robot_front_marker";
    case ObjectKind::robot_back_marker:
      return "robot_back_marker";
  }
  return "unknown";
}

void RobotBox::validate() const {
  require(pose.position.allFinite() && std::isfinite(pose.heading_rad), "robot.pose",
          "must be finite");
  require(positive(length_m), "robot.length_m", "must be positive");
  require(positive(width_m), "robot.width_m", "must be positive");
  require(positive(height_m), "robot.height_m", "must be positive");
  require(positive(marker_radius_m), "robot.marker_radius_m", "must be positive");
  require(std::isfinite(marker_inset_m) && marker_inset_m >= 0.0 && marker_inset_m < length_m / 2.0,
          "robot.marker_inset_m", "must be in [0, length_m / 2)");
}

SceneSphere RobotBox::front_marker() const {
  return marker(*this, ObjectKind::robot_front_marker, length_m / 2.0 - marker_inset_m,
                front_marker_bgr);
}

SceneSphere RobotBox::back_marker() const {
  return marker(*this, ObjectKind::robot_back_marker, -(length_m / 2.0 - marker_inset_m),
                back_marker_bgr);
}

void Lighting::validate() const {
  require(to_sun.allFinite() && std::abs(to_sun.norm() - 1.0) < 1e-6 && to_sun.z() > 0.0,
          "lighting.to_sun", "must be a unit vector pointing up (z > 0)");
  require(std::isfinite(ambient) && ambient >= 0.0 && ambient <= 1.0, "lighting.ambient",
          "must be in [0, 1]");
  if (shadow) {
    require(shadow->point_in_field.allFinite(), "lighting.shadow.point_in_field", "must be finite");
    require(shadow->direction.allFinite() && std::abs(shadow->direction.norm() - 1.0) < 1e-6,
            "lighting.shadow.direction", "must be a unit vector");
    require(positive(shadow->width_m), "lighting.shadow.width_m", "must be positive");
    require(std::isfinite(shadow->soft_edge_m) && shadow->soft_edge_m >= 0.0,
            "lighting.shadow.soft_edge_m", "must be non-negative");
  }
}

double Lighting::sun_visibility(const Vec2& p_in_field) const {
  if (!shadow) return 1.0;
  const Vec2 normal(-shadow->direction.y(), shadow->direction.x());
  const double distance = std::abs(normal.dot(p_in_field - shadow->point_in_field));
  const double outside = distance - shadow->width_m / 2.0;  // > 0 outside the umbra
  if (shadow->soft_edge_m <= 0.0) return outside > 0.0 ? 1.0 : 0.0;
  return std::clamp(0.5 + outside / shadow->soft_edge_m, 0.0, 1.0);
}

double Lighting::irradiance(const Vec3& normal, const Vec3& p_in_field) const {
  const double lambert = std::max(0.0, normal.dot(to_sun));
  return ambient + (1.0 - ambient) * lambert * sun_visibility(p_in_field.head<2>());
}

void CourtScene::validate() const {
  for (size_t i = 0; i < balls.size(); ++i) {
    const SceneSphere& b = balls[i];
    const std::string where = "balls[" + std::to_string(i) + "]";
    require(b.kind == ObjectKind::tennis_ball || b.kind == ObjectKind::reference_ball,
            where + ".kind", "must be tennis_ball or reference_ball");
    require(positive(b.radius_m) && b.radius_m < 1.0, where + ".radius_m", "must be in (0, 1) m");
    require(b.center_in_field.allFinite(), where + ".center_in_field", "must be finite");
    require(b.center_in_field.z() >= b.radius_m - 1e-9, where + ".center_in_field",
            "the ball must not sink into the floor (z >= radius)");
  }
  robot.validate();
  lighting.validate();
  effects.validate();
}

std::vector<SceneSphere> CourtScene::spheres() const {
  std::vector<SceneSphere> all = balls;
  all.push_back(robot.front_marker());
  all.push_back(robot.back_marker());
  return all;
}

}  // namespace ballsight::sim
