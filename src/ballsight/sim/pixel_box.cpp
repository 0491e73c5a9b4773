#include "ballsight/sim/pixel_box.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ballsight/sim/silhouette.hpp"

namespace ballsight::sim {
namespace {

/// Bounding box of projected points plus a margin, clipped; the whole image when a point fails
/// to project (part of the object is outside the lens model's range).
PixelBox box_around(const std::vector<std::optional<Vec2>>& pixels, const cv::Size& size) {
  constexpr double kMarginPx = 2.0;
  double x_min = INFINITY, y_min = INFINITY, x_max = -INFINITY, y_max = -INFINITY;
  for (const auto& p : pixels) {
    if (!p) return {0, 0, size.width, size.height};
    x_min = std::min(x_min, p->x());
    x_max = std::max(x_max, p->x());
    y_min = std::min(y_min, p->y());
    y_max = std::max(y_max, p->y());
  }
  const auto clip = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
  };
  return {clip(std::floor(x_min - kMarginPx), size.width),
          clip(std::floor(y_min - kMarginPx), size.height),
          clip(std::ceil(x_max + kMarginPx) + 1.0, size.width),
          clip(std::ceil(y_max + kMarginPx) + 1.0, size.height)};
}

}  // namespace

PixelBox sphere_pixel_box(const CourtCamera& camera, const SceneSphere& sphere,
                          const cv::Size& size) {
  const Vec3 c = camera.camera_from_field * sphere.center_in_field;
  if (c.z() < -sphere.radius_m) return {};  // wholly behind the camera
  const auto rim = sphere_outline_pixels(camera.camera, c, sphere.radius_m, 32);
  if (!rim) return {0, 0, size.width, size.height};
  std::vector<std::optional<Vec2>> pixels(rim->begin(), rim->end());
  return box_around(pixels, size);
}

PixelBox floor_box_pixel_box(const CourtCamera& camera, const FloorBox& box, const cv::Size& size) {
  constexpr int kPerEdge = 8;
  const Rigid2 field_from_box = box.pose.field_from_robot();
  std::vector<std::optional<Vec2>> pixels;
  const auto corner = [&](int i) {
    const Vec2 xy = field_from_box * Vec2((i & 1 ? 1 : -1) * box.half_size.x(),
                                          (i & 2 ? 1 : -1) * box.half_size.y());
    return Vec3(xy.x(), xy.y(), i & 4 ? box.height : 0.0);
  };
  for (int a = 0; a < 8; ++a) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (a & bit) continue;
      const Vec3 p0 = corner(a), p1 = corner(a | bit);
      for (int k = 0; k <= kPerEdge; ++k) {
        const Vec3 p = p0 + (p1 - p0) * (static_cast<double>(k) / kPerEdge);
        pixels.push_back(camera.camera.project(camera.camera_from_field * p));
      }
    }
  }
  return box_around(pixels, size);
}

}  // namespace ballsight::sim
