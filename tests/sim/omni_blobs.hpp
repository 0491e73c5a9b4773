#pragma once
// Test helpers: segment the simulator's object colours in a clean render (cv::inRange) and
// measure blobs (cv::moments, connected components), independently of the renderer.

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/omni_scene.hpp"

namespace ballsight::sim::test {

/// The ball's orange under any shading: hue of the palette colour, saturated, not too dark.
inline cv::Mat ball_mask(const cv::Mat& bgr) {
  cv::Mat hsv, mask;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  cv::inRange(hsv, cv::Scalar(5, 200, 60), cv::Scalar(25, 255, 255), mask);
  return mask;
}

/// How much of each pixel a flat `colour` covers (CV_32F in [0, 1]), from a render `with` the
/// coloured objects and one `without` them: with = a * colour + (1 - a) * without.
inline cv::Mat coverage(const cv::Mat& with, const cv::Mat& without, const cv::Vec3b& colour) {
  cv::Mat a(with.size(), CV_32F, cv::Scalar(0));
  for (int y = 0; y < with.rows; ++y) {
    for (int x = 0; x < with.cols; ++x) {
      const cv::Vec3d i(with.at<cv::Vec3b>(y, x));
      const cv::Vec3d f(without.at<cv::Vec3b>(y, x));
      const cv::Vec3d m(colour);
      const double denominator = (m - f).dot(m - f);
      if (denominator > 0.0)
        a.at<float>(y, x) =
            static_cast<float>(std::clamp((i - f).dot(m - f) / denominator, 0.0, 1.0));
    }
  }
  return a;
}

struct Blob {
  Vec2 centroid = Vec2::Zero();
  double area_px = 0.0;
  cv::Rect box;
};

/// Centroid of all set pixels (pixel centres at integer coordinates); nullopt when empty.
inline std::optional<Blob> mask_blob(const cv::Mat& mask) {
  const cv::Moments m = cv::moments(mask, true);
  if (m.m00 <= 0.0) return std::nullopt;
  return Blob{{m.m10 / m.m00, m.m01 / m.m00}, m.m00, cv::boundingRect(mask)};
}

/// Every 8-connected blob of a mask.
inline std::vector<Blob> mask_blobs(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  std::vector<Blob> blobs;
  for (int i = 1; i < n; ++i) {
    blobs.push_back({{centroids.at<double>(i, 0), centroids.at<double>(i, 1)},
                     static_cast<double>(stats.at<int>(i, cv::CC_STAT_AREA)),
                     {stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                      stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT)}});
  }
  return blobs;
}

}  // namespace ballsight::sim::test
