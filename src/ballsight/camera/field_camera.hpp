#pragma once
// A fixed camera placed on a field: its intrinsics (pinhole + OpenCV distortion) and its pose.
// What a calibrated court camera is at run time; the rays it gives are what pixel -> field
// intersects with a plane.

#include <optional>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct FieldCamera {
  PinholeCamera camera;
  Rigid3 camera_from_field;  // p_in_camera = camera_from_field * p_in_field (OpenCV rvec, tvec)

  Vec3 center_in_field() const;
  /// Field point -> pixel; nullopt behind the camera or outside the lens model's valid region.
  std::optional<Vec2> pixel_from_field(const Vec3& p_in_field) const;
  /// Pixel -> unit direction of its ray in the field frame (from center_in_field()).
  std::optional<Vec3> ray_in_field(const Vec2& pixel) const;
  /// Where the ray through `pixel` meets the horizontal plane z = `z_m` in front of the camera;
  /// nullopt where it does not (parallel, behind, or outside the lens model).
  std::optional<Vec3> point_at_height(const Vec2& pixel, double z_m) const;
};

}  // namespace ballsight
