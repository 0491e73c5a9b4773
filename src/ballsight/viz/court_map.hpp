#pragma once
// Top-down maps of the field: where a field point lands in the picture, and a court's floor
// (run-off, court, lines, net) drawn from plain values (eval/plot_inputs.hpp makes them from the
// simulator's court).

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/core/field_rect.hpp"
#include "ballsight/core/geometry.hpp"

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

/// A tennis court's floor as the maps draw it, field frame (origin at the court's centre on the
/// net line), metres, colours BGR.
struct CourtFloor {
  FieldRect surround;            // the run-off area
  FieldRect court;               // the doubles court
  std::vector<FieldRect> lines;  // the painted lines
  cv::Scalar surround_bgr, court_bgr, line_bgr;
  /// The net on x = 0 between posts at y = -net_posts_y_m and +net_posts_y_m; nullopt: no net.
  std::optional<double> net_posts_y_m;
  cv::Scalar net_bgr;
};

/// The run-off area, the court, its lines and its net.
void draw_court_floor(cv::Mat& image, const MapView& px, const CourtFloor& floor);

}  // namespace ballsight
