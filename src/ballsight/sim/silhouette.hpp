#pragma once
// Analytic outlines of the simulator's objects and their images: the rim a central camera sees
// of a sphere (its tangent circle), the rim of a flat disc on the floor, and the centroid of the
// projected outline. The truth uses these as a computation independent of per-pixel rendering.

#include <optional>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

/// Points of the circle along which rays from `viewpoint` graze the sphere (the silhouette's
/// preimage); empty when the viewpoint is inside the sphere.
std::vector<Vec3> sphere_silhouette(const Vec3& viewpoint, const Vec3& center, double radius,
                                    int samples);

/// Points of the rim of a disc lying on the floor (z = 0).
std::vector<Vec3> floor_disc_rim(const Vec2& center, double radius, int samples);

/// Projects robot-frame points through the rig's camera model without the mirror's clipping
/// circle (so outlines crossing the mirror edge keep their shape); nullopt if any point has no
/// projection.
std::optional<std::vector<Vec2>> project_outline(const OmniRig& rig,
                                                 const std::vector<Vec3>& points_in_robot);

/// Pixels of a sphere's outline in a pinhole camera (centre in the camera frame): the rim seen
/// from the optical centre, projected through the lens; nullopt when the camera is inside the
/// sphere or a rim point has no projection.
std::optional<std::vector<Vec2>> sphere_outline_pixels(const PinholeCamera& camera,
                                                       const Vec3& center_in_camera, double radius,
                                                       int samples);

/// True when every pixel lies inside the rig's mirror circle.
bool inside_mirror(const OmniRig& rig, const std::vector<Vec2>& pixels);

/// Area centroid of a simple polygon (shoelace formula); nullopt for a degenerate polygon.
std::optional<Vec2> polygon_centroid(const std::vector<Vec2>& polygon);

}  // namespace ballsight::sim
