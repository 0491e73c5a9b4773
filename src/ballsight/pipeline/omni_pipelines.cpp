#include "ballsight/pipeline/omni_pipelines.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/conventions.hpp"
#include "ballsight/detect/radial_scan.hpp"

namespace ballsight {

namespace {
constexpr ColorClassMask kBall = 1;

OmniBlobOptions blob_options(const GroundMap& map) {
  OmniBlobOptions options;
  options.image_center = map.info().image_center_px;
  options.min_radius_px = std::max(0.0, map.info().min_radius_px - 20.0);  // a ball's near edge
  options.max_radius_px = map.info().max_radius_px + 20.0;
  return options;
}

BallOnFloor with_map_height(BallOnFloor ball, const GroundMap& map) {
  if (map.info().viewpoint_height_cm > 0.0)
    ball.viewpoint_height_cm = map.info().viewpoint_height_cm;
  ball.validate();
  return ball;
}
}  // namespace

YuvRange yuv_range_around(const cv::Vec3b& bgr, double min_shade, int margin) {
  constexpr int kShades = 64;
  cv::Mat shades(1, kShades, CV_8UC3);
  for (int i = 0; i < kShades; ++i) {
    const double k = min_shade + (1.05 - min_shade) * i / (kShades - 1);
    for (int ch = 0; ch < 3; ++ch)
      shades.at<cv::Vec3b>(0, i)[ch] = cv::saturate_cast<uchar>(bgr[ch] * k);
  }
  cv::Mat yuv;
  cv::cvtColor(shades, yuv, cv::COLOR_BGR2YUV);
  YuvRange range{{255, 255, 255}, {0, 0, 0}};
  for (int i = 0; i < kShades; ++i) {
    for (int ch = 0; ch < 3; ++ch) {
      const int value = yuv.at<cv::Vec3b>(0, i)[ch];
      int& lo = range.min[static_cast<size_t>(ch)];
      int& hi = range.max[static_cast<size_t>(ch)];
      lo = std::max(0, std::min(lo, value - margin));
      hi = std::min(255, std::max(hi, value + margin));
    }
  }
  return range;
}

PaperOmniPipeline::PaperOmniPipeline(const YuvRange& ball, const Vec2& image_center,
                                     RadialDistanceFn distance_cm)
    : ball_(ball), image_center_(image_center), distance_cm_(std::move(distance_cm)) {
  ball_.validate("ball colour");
}

std::optional<Vec2> PaperOmniPipeline::locate_cm(const cv::Mat& bgr, const Pose2D& robot_cm) const {
  const cv::Mat1b mask = segment_yuv_inrange(bgr, ball_);
  const std::optional<Vec2> pixel = radial_scan_ball(mask, image_center_);  // Algorithm 3
  if (!pixel) return std::nullopt;
  const Polar polar = image_polar_from_pixel(*pixel, image_center_);  // Algorithm 4
  const std::optional<double> distance = distance_cm_(polar.theta_deg, polar.radius);  // Alg. 5
  if (!distance) return std::nullopt;
  return field_point_from_image_direction(robot_cm, polar.theta_deg, *distance);  // Algorithm 6
}

BallsightOmniPipeline::BallsightOmniPipeline(const YuvRange& ball_color, const GroundMap& map,
                                             BallOnFloor ball)
    : table_({{kBall, ball_color}}),
      map_(map),
      ball_(with_map_height(ball, map)),
      finder_(cv::Size(map.width(), map.height()), blob_options(map)) {}

std::optional<Vec2> BallsightOmniPipeline::locate_in_robot_cm(const cv::Mat& bgr) const {
  const std::vector<OmniBlob> blobs = finder_.find(bgr, table_, kBall);
  if (blobs.empty()) return std::nullopt;
  return ball_center_from_silhouette_cm(map_, blobs.front().pixels, ball_);
}

std::optional<Vec2> BallsightOmniPipeline::locate_cm(const cv::Mat& bgr,
                                                     const Pose2D& robot_cm) const {
  const std::optional<Vec2> p_in_robot = locate_in_robot_cm(bgr);
  if (!p_in_robot) return std::nullopt;
  return field_from_robot_point(robot_cm, *p_in_robot);
}

}  // namespace ballsight
