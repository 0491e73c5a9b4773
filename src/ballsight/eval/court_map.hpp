#pragma once
// Top-down maps of the field: where a field point lands in the picture, and the court's floor
// (run-off, court, lines, net) drawn from the simulator's court.

#include <opencv2/core.hpp>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight {

/// Field point (x, y) -> pixel offset + scale * (x - x0, y0 - y): field x to the right, y up.
struct MapView {
  Vec2 top_left_m;  // field coordinates of the view's top-left corner (x min, y max)
  double pixels_per_m = 40.0;
  cv::Point2d offset;

  cv::Point2d operator()(const Vec2& p) const {
    return offset + cv::Point2d((p.x() - top_left_m.x()) * pixels_per_m,
                                (top_left_m.y() - p.y()) * pixels_per_m);
  }
};

/// The run-off area, the court, its lines and its net.
void draw_court_floor(cv::Mat& image, const MapView& px, const sim::TennisCourtSpec& court);

}  // namespace ballsight
