#pragma once
// The outline of a sphere in a distorted pinhole image, computed analytically: the rim (the circle
// of points where viewing rays graze the sphere) projected point by point. Its polygon centroid is
// the true centre of the ball's blob, independent of any rendering; under perspective and lens
// distortion it differs from the projection of the sphere's centre.

#include <optional>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

/// Pixels of `count` rim points of the sphere, in order around it; nullopt when the camera is
/// inside the sphere or a rim point does not project.
std::optional<std::vector<Vec2>> sphere_silhouette(const PinholeCamera& camera,
                                                   const Vec3& center_in_camera, double radius,
                                                   int count = 96);

/// Area centroid of a simple polygon (shoelace formula); the vertex mean when degenerate.
Vec2 polygon_centroid(const std::vector<Vec2>& polygon);

}  // namespace ballsight::sim
