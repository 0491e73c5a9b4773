#pragma once
// Cameras for tests: a camera looking straight down (every ball on the floor looks the same size)
// and 1280 x 720 pinhole cameras (fx 800, no distortion) on 5 m poles at the four corners of a
// 36 x 18 m area, aimed at the court centre, as in the simulator's rig.

#include <vector>

#include "ballsight/camera/field_camera.hpp"

namespace ballsight::test {

/// `size` pixels, fx = fy = `fx`, no distortion, optical centre `height_m` above the field origin,
/// looking straight down (image x along field x, image y along field -y).
inline FieldCamera overhead_camera(cv::Size size, double fx, double height_m) {
  PinholeParams p;
  p.width = size.width;
  p.height = size.height;
  p.fx = p.fy = fx;
  p.cx = 0.5 * (size.width - 1);
  p.cy = 0.5 * (size.height - 1);
  Rigid3 camera_from_field;
  camera_from_field.rotation << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  camera_from_field.translation = Vec3(0.0, 0.0, height_m);
  return {PinholeCamera(p), camera_from_field};
}

/// A camera at `eye` looking at `target`, image x to the right of the view, y down.
inline FieldCamera camera_looking_at(const Vec3& eye, const Vec3& target) {
  PinholeParams p;
  p.width = 1280;
  p.height = 720;
  p.fx = p.fy = 800.0;
  p.cx = 639.5;
  p.cy = 359.5;
  const Vec3 z = (target - eye).normalized();
  const Vec3 x = z.cross(Vec3::UnitZ()).normalized();
  const Vec3 y = z.cross(x);
  Rigid3 camera_from_field;
  camera_from_field.rotation.row(0) = x.transpose();
  camera_from_field.rotation.row(1) = y.transpose();
  camera_from_field.rotation.row(2) = z.transpose();
  camera_from_field.translation = -(camera_from_field.rotation * eye);
  return {PinholeCamera(p), camera_from_field};
}

inline std::vector<FieldCamera> corner_cameras() {
  std::vector<FieldCamera> cameras;
  for (const Vec2& corner : {Vec2(18, 9), Vec2(18, -9), Vec2(-18, -9), Vec2(-18, 9)})
    cameras.push_back(camera_looking_at(Vec3(corner.x(), corner.y(), 5.0), Vec3(0, 0, 0)));
  return cameras;
}

}  // namespace ballsight::test
