#pragma once
// Synthetic images for the court detector tests: a camera looking straight down on a green floor
// (so every ball looks the same size) and anti-aliased balls drawn on it by supersampling.

#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

#include "field_cameras.hpp"

namespace ballsight::test {

inline const cv::Vec3b kCourtGreen{88, 128, 70};
inline const cv::Vec3b kBallYellow{45, 250, 225};

/// 640 x 480, fx = fy = 800, optical centre 6 m above the field origin, looking straight down.
inline FieldCamera overhead_camera() {
  return overhead_camera({640, 480}, 800.0, 6.0);
}

/// Apparent radius of a tennis ball on the floor under overhead_camera().
inline double overhead_ball_radius_px() {
  return 800.0 * 0.0335 / (6.0 - 0.0335);
}

struct Disc {
  Vec2 center_px;
  double radius_px;
  cv::Vec3b bgr;
};

/// The floor colour with discs drawn over it (8 x 8 samples per pixel, later discs on top) and
/// Gaussian noise of `noise_sigma` grey levels.
inline cv::Mat draw_discs(const std::vector<Disc>& discs, double noise_sigma = 0.0,
                          std::uint64_t seed = 1, cv::Size size = {640, 480},
                          const cv::Vec3b& floor = kCourtGreen) {
  cv::Mat3f image(size, cv::Vec3f(floor[0], floor[1], floor[2]));
  constexpr int kSamples = 8;
  for (const Disc& d : discs) {
    const int x0 = static_cast<int>(std::floor(d.center_px.x() - d.radius_px - 1));
    const int y0 = static_cast<int>(std::floor(d.center_px.y() - d.radius_px - 1));
    const int x1 = static_cast<int>(std::ceil(d.center_px.x() + d.radius_px + 1));
    const int y1 = static_cast<int>(std::ceil(d.center_px.y() + d.radius_px + 1));
    for (int y = std::max(0, y0); y <= std::min(size.height - 1, y1); ++y) {
      for (int x = std::max(0, x0); x <= std::min(size.width - 1, x1); ++x) {
        int inside = 0;
        for (int sy = 0; sy < kSamples; ++sy)
          for (int sx = 0; sx < kSamples; ++sx) {
            const Vec2 p(x - 0.5 + (sx + 0.5) / kSamples, y - 0.5 + (sy + 0.5) / kSamples);
            inside += (p - d.center_px).norm() <= d.radius_px;
          }
        const float a = static_cast<float>(inside) / (kSamples * kSamples);
        image(y, x) = (1.0f - a) * image(y, x) + a * cv::Vec3f(d.bgr[0], d.bgr[1], d.bgr[2]);
      }
    }
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> noise(0.0f, static_cast<float>(noise_sigma));
  cv::Mat3b out(size);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      for (int c = 0; c < 3; ++c)
        out(y, x)[c] =
            cv::saturate_cast<uchar>(image(y, x)[c] + (noise_sigma > 0 ? noise(rng) : 0.0f));
  return out;
}

}  // namespace ballsight::test
