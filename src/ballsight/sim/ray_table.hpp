#pragma once
// Per-pixel viewing rays of a pinhole camera, computed once (PinholeCamera::unproject) and looked
// up while rendering; sub-pixel rays for supersampling are bilinear interpolations of the table.
// Unprojecting is a Newton solve per ray, far too slow to repeat for every sample of every view.

#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

class RayTable {
 public:
  /// Rays of every pixel centre, rotated into a frame by `frame_from_camera` (identity: camera
  /// frame). Pixels where the model is not invertible hold a zero vector.
  explicit RayTable(const PinholeCamera& camera, const Mat3& frame_from_camera = Mat3::Identity());

  int width() const { return width_; }
  int height() const { return height_; }

  /// Unit ray through the centre of pixel (x, y).
  Vec3 at(int x, int y) const {
    const float* r = &rays_[3 * (static_cast<size_t>(y) * width_ + x)];
    return {r[0], r[1], r[2]};
  }
  /// Unit ray through the sub-pixel point (x, y), pixel centres at integers; bilinear between the
  /// four nearest pixel rays (extrapolated linearly beyond the outermost pixel centres).
  Vec3 interpolate(double x, double y) const;
  /// Ray of sample (sx, sy) of an n x n grid over pixel (x, y), at offsets (s + 0.5) / n - 0.5
  /// from the pixel centre; the middle sample of an odd grid is the pixel's own ray.
  Vec3 sample(int x, int y, int sx, int sy, int n) const {
    if (2 * sx + 1 == n && 2 * sy + 1 == n) return at(x, y);
    return interpolate(x + (sx + 0.5) / n - 0.5, y + (sy + 0.5) / n - 0.5);
  }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<float> rays_;  // 3 per pixel, row-major
};

}  // namespace ballsight::sim
