#pragma once
// Algorithm 3 of the omnivision paper ("Find Ball on Camera"), kept as the baseline detector:
// rays every 2.5 degrees from the image centre, 1 px steps out to 320 px, first ball pixel.

#include <opencv2/core.hpp>
#include <optional>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct RadialScanOptions {
  double angle_step_deg = 2.5;
  int max_radius_px = 320;
};

/// As printed: each ray that meets a ball pixel overwrites the result, so the answer is the
/// first ball pixel (integer coordinates) on the last such ray; nullopt when no ray meets one.
std::optional<Vec2> radial_scan_ball(const cv::Mat1b& ball_mask, const Vec2& image_center,
                                     const RadialScanOptions& options = {});

}  // namespace ballsight
