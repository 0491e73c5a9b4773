#pragma once
// Cameras for world tests: 1280 x 720 pinhole cameras (fx 800, no distortion) on 5 m poles at the
// four corners of an 36 x 18 m area, aimed at the court centre, as in the simulator's rig.

#include <vector>

#include "ballsight/camera/field_camera.hpp"

namespace ballsight::test {

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
