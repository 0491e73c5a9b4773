#pragma once
// Where an object can appear in a court camera's image: the bounding box of its projected outline
// plus a margin, so that the renderer ray-casts it only there.

#include <opencv2/core.hpp>

#include "ballsight/core/raycast_box.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scene.hpp"

namespace ballsight::sim {

/// Pixel rectangle [x0, x1) x [y0, y1), clipped to the image.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

/// Pixels a sphere can cover (from its outline); empty when it is wholly behind the camera, the
/// whole image when part of its outline does not project.
PixelBox sphere_pixel_box(const CourtCamera& camera, const SceneSphere& sphere,
                          const cv::Size& size);

/// Pixels a box on the floor can cover (points along its edges: lens distortion bows them); the
/// whole image when one of them does not project.
PixelBox floor_box_pixel_box(const CourtCamera& camera, const FloorBox& box, const cv::Size& size);

}  // namespace ballsight::sim
