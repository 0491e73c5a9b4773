#pragma once
// Bright peaks along a ray of a grey image: white lines crossing it (the omni image's floor lines
// and the rings a spinning robot sees them as).

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct RayPeak {
  double radius_px = 0.0;  // the peak's centre along the ray
  double height = 0.0;     // grey levels above the local background
};

struct RayPeakOptions {
  double min_contrast = 25.0;  // grey levels a peak stands above its background
  double background_px = 5.0;  // half-width of the top-hat's window (lines are narrower)
};

/// The bright peaks along the ray from `center` at image angle `theta_deg`, radii r0 to r1: the
/// white top-hat of the ray's profile (the profile minus its opening) at least min_contrast, each
/// peak's centre the centroid of the top-hat above half its height. Nearest first.
std::vector<RayPeak> ray_peaks(const cv::Mat1b& grey, const Vec2& center, double theta_deg,
                               double r0, double r1, const RayPeakOptions& options);

}  // namespace ballsight
