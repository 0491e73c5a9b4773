#pragma once
// Blobs of one colour in a BGR image, found by hue, saturation and value around a nominal colour
// (OpenCV's HSV) and connected components; each blob's centroid is weighted by how much of the
// colour each pixel holds, so that blobs of a few pixels (a 2 cm reference ball 15 m away is about
// 1 px in radius) are located to a fraction of a pixel. Used to find the reference balls for a
// fixed camera's extrinsic calibration.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct ColorBlobOptions {
  cv::Vec3b target_bgr{20, 100, 255};  // nominal colour in daylight (orange table-tennis ball)
  double hue_tolerance_deg = 20.0;     // on the 360-degree hue circle
  double min_saturation = 0.45;        // HSV saturation, 0-1
  double min_value = 0.12;             // HSV value, 0-1
  int min_area_px = 1;
  int max_area_px = 2000;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct ColorBlob {
  Vec2 centroid_px = Vec2::Zero();  // colour-weighted, pixel centres at integer coordinates
  int area_px = 0;                  // pixels inside the thresholds
  cv::Rect bbox;
};

/// Every blob of the colour with an area in [min_area_px, max_area_px], largest first.
std::vector<ColorBlob> find_color_blobs(const cv::Mat& bgr, const ColorBlobOptions& options);

}  // namespace ballsight
