#include "ballsight/eval/court_map.hpp"

#include <opencv2/imgproc.hpp>

namespace ballsight {

void draw_court_floor(cv::Mat& image, const MapView& px, const sim::TennisCourtSpec& court) {
  const auto fill_rect = [&](const sim::GroundRect& r, const cv::Vec3b& bgr) {
    cv::rectangle(image, px({r.x_min, r.y_max}), px({r.x_max, r.y_min}),
                  cv::Scalar(bgr[0], bgr[1], bgr[2]), cv::FILLED);
  };
  fill_rect(court.surround_rect(), court.surround_bgr);
  fill_rect(court.court_rect(), court.court_bgr);
  for (const sim::GroundRect& line : court.line_rects()) fill_rect(line, court.line_bgr);
  if (!court.net.enabled) return;
  const double post_y = court.doubles_width_m / 2.0 + court.net.post_outside_doubles_m;
  const cv::Scalar mesh(court.net.mesh_bgr[0], court.net.mesh_bgr[1], court.net.mesh_bgr[2]);
  cv::line(image, px({0.0, -post_y}), px({0.0, post_y}), mesh, 3, cv::LINE_AA);
  for (const double y : {-post_y, post_y}) {
    cv::circle(image, px({0.0, y}), 4, mesh, cv::FILLED, cv::LINE_AA);
  }
}

}  // namespace ballsight
