#pragma once
// The tennis-ball-collecting-robot report's detector, kept as the baseline (sections 2.2, 2.3,
// 7.1, 7.6): convert to HSV, threshold, 5x5 median filter, contours, centre of mass of each
// contour. The robot's pink front and blue back markers go through the same steps with their own
// thresholds. Every pixel of the image is converted, thresholded and filtered.

#include <array>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/pixel_detection.hpp"

namespace ballsight {

/// A box in OpenCV's 8-bit HSV (cv::COLOR_BGR2HSV: H 0-179, S and V 0-255), bounds inclusive.
struct HsvRange {
  std::array<int, 3> min{0, 0, 0};
  std::array<int, 3> max{179, 255, 255};

  /// Throws InputError naming `name` when a bound is out of range or min > max.
  void validate(const char* name) const;
  /// Whether the 8-bit BGR colour converts to HSV inside the box.
  bool contains_bgr(const cv::Vec3b& bgr) const;
};

/// The hue of an 8-bit BGR colour in OpenCV's 8-bit HSV scale (0-179).
int opencv_hue(const cv::Vec3b& bgr);

/// `range` moved along the hue axis by the hue difference from `from_bgr` to `to_bgr`: a box
/// chosen around one colour, for another (its hue bounds clamped to 0-179, S and V kept; a box
/// cannot cross hue 0, so a red colour's may miss half of its hues: check with contains_bgr).
HsvRange hue_moved(const HsvRange& range, const cv::Vec3b& from_bgr, const cv::Vec3b& to_bgr);

struct SeedDetectorOptions {
  // Section 2.3: H 19-39, S 119-255, V 4-206, found by trial; the values are already in OpenCV's
  // 8-bit HSV scale. V max raised from 206 to 255: the simulator's sunlit balls are brighter
  // than the report's (see docs/court-eval.md).
  HsvRange ball{{19, 119, 4}, {39, 255, 255}};
  // The report gives no values for the markers; chosen as its user would, around their hues
  // (for markers of other colours: hue_moved, as pipeline/site_setup.hpp does).
  HsvRange front_marker{{150, 100, 40}, {175, 255, 255}};  // pink, hue 163
  HsvRange back_marker{{100, 120, 30}, {125, 255, 255}};   // blue, hue 112
  int median_kernel_px = 5;                                // section 7.1: 5x5

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Centres of mass of the contours of one colour range: threshold, median filter (skipped when
/// `median_kernel_px` is 1), contours, moments. Largest contour first.
std::vector<PixelDetection> detect_seed_colour(const cv::Mat& bgr, const HsvRange& range,
                                               int median_kernel_px, ObjectClass object);

/// Every contour's centre of mass, for the balls and both markers (cv::moments of the contour; a
/// contour of zero area, one or two pixels after the threshold, gives the mean of its points).
/// The image is 8-bit BGR.
std::vector<PixelDetection> detect_seed(const cv::Mat& bgr, const SeedDetectorOptions& options);

}  // namespace ballsight
