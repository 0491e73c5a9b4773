#pragma once
// The floor as a central catadioptric camera sees it: the unified model (Mei & Rives 2007,
// camera/unified_model.hpp) at a height above the floor, its axis turned from
// the ideal mount by a small rotation (tilt and yaw). The physics of camera/omni_rig.hpp, with
// the parameters ballsight's omni model fits, plus an optional radial distortion for mirrors
// that are not exactly central. Templated on the scalar for Ceres' autodiff.

#include <ceres/rotation.h>

#include <array>

#include "ballsight/camera/unified_model.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct CatadioptricFloorParams {
  double xi = 0.5;
  double focal_px = 128.0;
  Vec2 principal_px{319.5, 239.5};
  double height_cm = 60.0;           // effective viewpoint above the floor
  Vec3 rotation_rad = Vec3::Zero();  // angle-axis, robot frame: mount error from the ideal

  /// Radial distortion in the pixel -> ray direction: the normalised image point m_d becomes
  /// m_d (1 + q1 |m_d|^2 + q2 |m_d|^4 + q3 |m_d|^6).
  Vec3 distortion = Vec3::Zero();

  static constexpr int kSize = 11;
  static constexpr int kDistortionIndex = 8;
  std::array<double, kSize> to_array() const {
    return {xi,
            focal_px,
            principal_px.x(),
            principal_px.y(),
            height_cm,
            rotation_rad.x(),
            rotation_rad.y(),
            rotation_rad.z(),
            distortion.x(),
            distortion.y(),
            distortion.z()};
  }
  static CatadioptricFloorParams from_array(const std::array<double, kSize>& a) {
    return {a[0], a[1], {a[2], a[3]}, a[4], {a[5], a[6], a[7]}, {a[8], a[9], a[10]}};
  }
};

/// Pixel (u, v) -> floor point (cm, robot frame) for parameters `p` laid out as to_array().
/// Returns false when the pixel's ray misses the floor (above the horizon or outside the model).
/// With `clamp_horizon` a ray at or above the horizon is instead bent down to a grazing one, so
/// a fit from a poor start sees a large finite residual rather than a failure.
template <typename T>
bool floor_point_from_pixel(const T* p, const T& u, const T& v, T* floor_cm,
                            bool clamp_horizon = false) {
  const T dx = (u - p[2]) / p[1];
  const T dy = (v - p[3]) / p[1];
  const T d2 = dx * dx + dy * dy;
  const T radial = T(1.0) + d2 * (p[8] + d2 * (p[9] + d2 * p[10]));
  const T mx = dx * radial;
  const T my = dy * radial;
  T lifted[3];
  if (!UnifiedModel<T>{p[0]}.lift(mx, my, lifted)) return false;
  // Ideal mount: image right is the robot's right, image down is backwards, the axis points
  // down (camera/omni_rig.cpp), then the mount error.
  const T ideal[3] = {-lifted[1], -lifted[0], -lifted[2]};
  T ray[3];
  ceres::AngleAxisRotatePoint(p + 5, ideal, ray);
  T down = -ray[2];
  constexpr double kGrazing = 1e-3;
  if (!(down > T(kGrazing))) {
    if (!clamp_horizon) return false;
    down = T(kGrazing);
  }
  const T scale = p[4] / down;
  floor_cm[0] = scale * ray[0];
  floor_cm[1] = scale * ray[1];
  return true;
}

/// Floor point (cm, robot frame) -> pixel for parameters `p` laid out as to_array(), the inverse
/// of floor_point_from_pixel for a model without distortion (p[8..10] are ignored). Returns false
/// when the point is not in front of the mirror.
template <typename T>
bool pixel_from_floor_point(const T* p, const T* floor_cm, T* pixel) {
  const T viewpoint_to_point[3] = {floor_cm[0], floor_cm[1], -p[4]};
  const T inverse_rotation[3] = {-p[5], -p[6], -p[7]};
  T ray[3];
  ceres::AngleAxisRotatePoint(inverse_rotation, viewpoint_to_point, ray);
  // The ideal mount's axes (floor_point_from_pixel), back to the camera's.
  const T in_camera[3] = {-ray[1], -ray[0], -ray[2]};
  T m[2];
  if (!UnifiedModel<T>{p[0]}.project(in_camera, m)) return false;
  pixel[0] = p[1] * m[0] + p[2];
  pixel[1] = p[1] * m[1] + p[3];
  return true;
}

}  // namespace ballsight
