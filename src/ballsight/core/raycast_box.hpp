#pragma once
// Ray casting against a box standing on the floor with a heading (an oriented box whose faces are
// vertical or horizontal), by the slab method (Kay & Kajiya 1986): the simulator renders the
// robot with it, the world model asks whether the robot hides a ball from a camera.

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// A box on the floor: footprint centred on `pose` with `half_size` (x along the heading, y), z in
/// [0, height].
struct FloorBox {
  Pose2D pose;
  Vec2 half_size = Vec2::Zero();
  double height = 0.0;
};

struct BoxHit {
  double t = 0.0;
  Vec3 normal_in_field = Vec3::Zero();  // outward normal of the face hit
};

/// First hit of the ray `origin + t * direction` (unit direction, field frame) with the box, from
/// outside; nullopt when it misses or the origin is inside.
inline std::optional<BoxHit> intersect_floor_box(const Vec3& origin, const Vec3& direction,
                                                 const FloorBox& box) {
  const double c = std::cos(box.pose.heading_rad), s = std::sin(box.pose.heading_rad);
  const Vec3 o_rel = origin - Vec3(box.pose.position.x(), box.pose.position.y(), 0.0);
  // Into the box frame (rotate by -heading about z).
  const Vec3 o(c * o_rel.x() + s * o_rel.y(), -s * o_rel.x() + c * o_rel.y(), o_rel.z());
  const Vec3 d(c * direction.x() + s * direction.y(), -s * direction.x() + c * direction.y(),
               direction.z());
  const Vec3 lo(-box.half_size.x(), -box.half_size.y(), 0.0);
  const Vec3 hi(box.half_size.x(), box.half_size.y(), box.height);
  double t_near = -INFINITY, t_far = INFINITY;
  int axis_near = 0;
  double sign_near = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-15) {
      if (o[axis] < lo[axis] || o[axis] > hi[axis]) return std::nullopt;
      continue;
    }
    double t0 = (lo[axis] - o[axis]) / d[axis];
    double t1 = (hi[axis] - o[axis]) / d[axis];
    double sign = -1.0;  // entering through the low face
    if (t0 > t1) {
      std::swap(t0, t1);
      sign = 1.0;
    }
    if (t0 > t_near) {
      t_near = t0;
      axis_near = axis;
      sign_near = sign;
    }
    t_far = std::min(t_far, t1);
    if (t_near > t_far) return std::nullopt;
  }
  if (!(t_near > 1e-9)) return std::nullopt;
  Vec3 n_box = Vec3::Zero();
  n_box[axis_near] = sign_near;
  const Vec3 normal(c * n_box.x() - s * n_box.y(), s * n_box.x() + c * n_box.y(), n_box.z());
  return BoxHit{t_near, normal};
}

/// Whether the box stands between `eye` and `point` (the segment from one to the other meets it).
inline bool box_hides(const Vec3& eye, const Vec3& point, const FloorBox& box) {
  const double distance = (point - eye).norm();
  if (!(distance > 0.0)) return false;
  const std::optional<BoxHit> hit = intersect_floor_box(eye, (point - eye) / distance, box);
  return hit && hit->t < distance;
}

}  // namespace ballsight
