#include "ballsight/sim/ray_table.hpp"

#include <algorithm>
#include <cmath>

namespace ballsight::sim {

RayTable::RayTable(const PinholeCamera& camera, const Mat3& frame_from_camera)
    : width_(camera.width()),
      height_(camera.height()),
      rays_(3 * static_cast<size_t>(camera.width()) * camera.height(), 0.0f) {
  float* out = rays_.data();
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x, out += 3) {
      const std::optional<Vec3> ray =
          camera.unproject(Vec2(static_cast<double>(x), static_cast<double>(y)));
      if (!ray) continue;
      const Vec3 r = frame_from_camera * *ray;
      out[0] = static_cast<float>(r.x());
      out[1] = static_cast<float>(r.y());
      out[2] = static_cast<float>(r.z());
    }
  }
}

Vec3 RayTable::interpolate(double x, double y) const {
  const int x0 = std::clamp(static_cast<int>(std::floor(x)), 0, std::max(0, width_ - 2));
  const int y0 = std::clamp(static_cast<int>(std::floor(y)), 0, std::max(0, height_ - 2));
  const int x1 = std::min(x0 + 1, width_ - 1), y1 = std::min(y0 + 1, height_ - 1);
  const double fx = x - x0, fy = y - y0;
  const Vec3 top = at(x0, y0) + fx * (at(x1, y0) - at(x0, y0));
  const Vec3 bottom = at(x0, y1) + fx * (at(x1, y1) - at(x0, y1));
  return (top + fy * (bottom - top)).normalized();
}

}  // namespace ballsight::sim
