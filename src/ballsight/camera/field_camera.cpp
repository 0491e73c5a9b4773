#include "ballsight/camera/field_camera.hpp"

#include <cmath>

namespace ballsight {

Vec3 FieldCamera::center_in_field() const {
  return -(camera_from_field.rotation.transpose() * camera_from_field.translation);
}

std::optional<Vec2> FieldCamera::pixel_from_field(const Vec3& p_in_field) const {
  return camera.project(camera_from_field * p_in_field);
}

std::optional<Vec3> FieldCamera::ray_in_field(const Vec2& pixel) const {
  const std::optional<Vec3> ray_in_camera = camera.unproject(pixel);
  if (!ray_in_camera) return std::nullopt;
  return camera_from_field.rotation.transpose() * *ray_in_camera;
}

std::optional<Vec3> FieldCamera::point_at_height(const Vec2& pixel, double z_m) const {
  const std::optional<Vec3> ray = ray_in_field(pixel);
  if (!ray || std::abs(ray->z()) < 1e-12) return std::nullopt;
  const Vec3 eye = center_in_field();
  const double t = (z_m - eye.z()) / ray->z();
  if (!(t > 0.0)) return std::nullopt;
  return eye + t * *ray;
}

}  // namespace ballsight
