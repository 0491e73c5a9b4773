#include "ballsight/viz/court_map.hpp"

#include <opencv2/imgproc.hpp>

namespace ballsight {

void draw_court_floor(cv::Mat& image, const MapView& px, const CourtFloor& floor) {
  const auto fill_rect = [&](const FieldRect& r, const cv::Scalar& bgr) {
    cv::rectangle(image, px({r.min_m.x(), r.max_m.y()}), px({r.max_m.x(), r.min_m.y()}), bgr,
                  cv::FILLED);
  };
  fill_rect(floor.surround, floor.surround_bgr);
  fill_rect(floor.court, floor.court_bgr);
  for (const FieldRect& line : floor.lines) fill_rect(line, floor.line_bgr);
  if (!floor.net_posts_y_m) return;
  const double post_y = *floor.net_posts_y_m;
  cv::line(image, px({0.0, -post_y}), px({0.0, post_y}), floor.net_bgr, 3, cv::LINE_AA);
  for (const double y : {-post_y, post_y}) {
    cv::circle(image, px({0.0, y}), 4, floor.net_bgr, cv::FILLED, cv::LINE_AA);
  }
}

}  // namespace ballsight
