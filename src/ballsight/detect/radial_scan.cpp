#include "ballsight/detect/radial_scan.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"

namespace ballsight {

std::optional<Vec2> radial_scan_ball(const cv::Mat1b& ball_mask, const Vec2& image_center,
                                     const RadialScanOptions& options) {
  std::optional<Vec2> found;
  for (double angle = 0.0; angle < 360.0; angle += options.angle_step_deg) {
    const double c = std::cos(rad_from_deg(angle)), s = std::sin(rad_from_deg(angle));
    for (int dist = 0; dist <= options.max_radius_px; ++dist) {
      // The paper truncates to int when indexing the frame.
      const int x = static_cast<int>(dist * c + image_center.x());
      const int y = static_cast<int>(image_center.y() - dist * s);
      if (x < 0 || y < 0 || x >= ball_mask.cols || y >= ball_mask.rows) break;
      if (ball_mask(y, x) == 255) {
        found = Vec2(x, y);
        break;
      }
    }
  }
  return found;
}

}  // namespace ballsight
