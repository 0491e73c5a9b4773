#include "ballsight/sim/court_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ballsight/core/enum_names.hpp"
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

constexpr EnumNames<LightCondition, 4> kLightConditions{
    {{LightCondition::sun, "sun"},
     {LightCondition::hard_shadow, "hard_shadow"},
     {LightCondition::overcast, "overcast"},
     {LightCondition::indoor, "indoor"}}};

}  // namespace

std::string_view light_condition_name(LightCondition condition) {
  return enum_name(kLightConditions, condition);
}

std::optional<LightCondition> light_condition_named(std::string_view name) {
  return enum_named(kLightConditions, name);
}

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

bool FloorLeaf::covers(const Vec2& p_in_field) const {
  const Vec2 d = p_in_field - center_in_field;
  const double u = d.dot(axis) / half_length_m,
               v = (d.x() * axis.y() - d.y() * axis.x()) / half_width_m;
  return u * u + v * v <= 1.0;
}

namespace {

/// First hit of a ray with an upright cylinder standing on the floor at `center`, from outside.
std::optional<BoxHit> intersect_floor_cylinder(const Vec3& origin, const Vec3& direction,
                                               const Vec2& center, double radius_m,
                                               double height_m) {
  const Vec3 o = origin - Vec3(center.x(), center.y(), 0.0);
  std::optional<BoxHit> best;
  // The side: |o_xy + t d_xy| = radius, with z in [0, height].
  const double a = direction.head<2>().squaredNorm();
  const double b = o.head<2>().dot(direction.head<2>());
  const double c = o.head<2>().squaredNorm() - radius_m * radius_m;
  if (a > 1e-15 && c > 0.0 && b * b - a * c >= 0.0) {
    const double t = (-b - std::sqrt(b * b - a * c)) / a;
    const Vec3 p = o + t * direction;
    if (t > 1e-9 && p.z() >= 0.0 && p.z() <= height_m)
      best = BoxHit{t, Vec3(p.x() / radius_m, p.y() / radius_m, 0.0)};
  }
  // The top, seen from above.
  if (o.z() > height_m && direction.z() < 0.0) {
    const double t = (height_m - o.z()) / direction.z();
    if ((o + t * direction).head<2>().squaredNorm() <= radius_m * radius_m &&
        (!best || t < best->t))
      best = BoxHit{t, Vec3::UnitZ()};
  }
  return best;
}

}  // namespace

std::optional<BoxHit> FloorBottle::intersect(const Vec3& origin, const Vec3& direction) const {
  return intersect_floor_cylinder(origin, direction, center_in_field, radius_m, height_m);
}

FloorBox FloorBottle::bounds() const {
  return {Pose2D{center_in_field, 0.0}, Vec2::Constant(radius_m), height_m};
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
  for (size_t i = 0; i < leaves.size(); ++i) {
    const FloorLeaf& leaf = leaves[i];
    const std::string where = "leaves[" + std::to_string(i) + "]";
    require(leaf.center_in_field.allFinite(), where + ".center_in_field", "must be finite");
    require(std::abs(leaf.axis.norm() - 1.0) < 1e-6, where + ".axis", "must be a unit vector");
    require(positive(leaf.half_length_m) && positive(leaf.half_width_m) &&
                leaf.half_length_m < 1.0 && leaf.half_width_m < 1.0,
            where, "half length and width must be in (0, 1) m");
  }
  for (size_t i = 0; i < bottles.size(); ++i) {
    const FloorBottle& bottle = bottles[i];
    const std::string where = "bottles[" + std::to_string(i) + "]";
    require(bottle.center_in_field.allFinite(), where + ".center_in_field", "must be finite");
    require(positive(bottle.radius_m) && positive(bottle.height_m) && bottle.radius_m < 1.0 &&
                bottle.height_m < 2.0,
            where, "radius must be in (0, 1) m and height in (0, 2) m");
  }
  for (size_t i = 0; i < obstacles.size(); ++i) {
    const CourtObstacle& o = obstacles[i];
    const std::string where = "obstacles[" + std::to_string(i) + "]";
    require(o.pose.position.allFinite() && std::isfinite(o.pose.heading_rad), where + ".pose",
            "must be finite");
    require(positive(o.half_size.x()) && positive(o.half_size.y()) && o.half_size.maxCoeff() < 2.0,
            where + ".half_size", "must be in (0, 2) m");
    require(positive(o.height_m) && o.height_m < 2.5, where + ".height_m", "must be in (0, 2.5) m");
    require(!o.walk_to || o.walk_to->allFinite(), where + ".walk_to", "must be finite");
    require(std::isfinite(o.walk_mps) && o.walk_mps >= 0.0 && o.walk_mps <= 2.0,
            where + ".walk_mps", "must be in [0, 2] m/s");
  }
  robot.validate();
  lighting.validate();
  effects.validate();
}

std::string_view obstacle_kind_name(ObstacleKind kind) {
  return kind == ObstacleKind::person ? "person" : "bag";
}

std::optional<BoxHit> CourtObstacle::intersect(const Vec3& origin, const Vec3& direction) const {
  if (kind == ObstacleKind::person)
    return intersect_floor_cylinder(origin, direction, pose.position, half_size.x(), height_m);
  return intersect_floor_box(origin, direction, bounds());
}

FloorBox CourtObstacle::bounds() const {
  if (kind == ObstacleKind::person)
    return {Pose2D{pose.position, 0.0}, Vec2::Constant(half_size.x()), height_m};
  return {pose, half_size, height_m};
}

double CourtObstacle::floor_distance(const Vec2& p) const {
  if (kind == ObstacleKind::person)
    return std::max(0.0, (p - pose.position).norm() - half_size.x());
  const Vec2 local = pose.field_from_robot().inverse() * p;
  return (local.cwiseAbs() - half_size).cwiseMax(0.0).norm();
}

std::vector<SceneSphere> CourtScene::spheres() const {
  std::vector<SceneSphere> all = balls;
  all.push_back(robot.front_marker());
  all.push_back(robot.back_marker());
  return all;
}

}  // namespace ballsight::sim
