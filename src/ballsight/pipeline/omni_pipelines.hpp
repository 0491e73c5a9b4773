#pragma once
// The two omni run-time pipelines, frame -> ball on the field, composed from the stages of the
// lower layers (segment -> detect -> pixel->ground -> field):
// - the omnivision paper's (Section IV): YUV threshold, the radial scan of Algorithm 3 for the
//   ball's first pixel, a radial distance read (Algorithms 4-5), Algorithm 6 to the field;
// - ballsight's: colour-class table, the whole ball blob's sub-pixel centroid, one ground-map
//   read, the ball-radius correction (world/ball_on_floor.hpp), robot -> field.

#include <functional>
#include <opencv2/core.hpp>
#include <optional>

#include "ballsight/camera/ground_map.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/color_classes.hpp"
#include "ballsight/detect/omni_blobs.hpp"
#include "ballsight/world/ball_on_floor.hpp"

namespace ballsight {

/// A YUV box around a colour as it appears under diffuse shading (shade factors `min_shade` to
/// 1.05 of `bgr`), widened by `margin` levels: how a user would pick thresholds by sampling the
/// ball in a few images.
YuvRange yuv_range_around(const cv::Vec3b& bgr, double min_shade = 0.4, int margin = 14);

/// Image angle (deg), pixel radius -> ground distance (cm); nullopt where unknown.
using RadialDistanceFn = std::function<std::optional<double>(double theta_deg, double radius_px)>;

class PaperOmniPipeline {
 public:
  PaperOmniPipeline(const YuvRange& ball, const Vec2& image_center, RadialDistanceFn distance_cm);

  /// The ball in the field frame (cm) for a robot at `robot_cm` (position in cm); nullopt when
  /// no ball pixel is found or the distance is unknown.
  std::optional<Vec2> locate_cm(const cv::Mat& bgr, const Pose2D& robot_cm) const;

 private:
  YuvRange ball_;
  Vec2 image_center_;
  RadialDistanceFn distance_cm_;
};

class BallsightOmniPipeline {
 public:
  /// `ball.viewpoint_height_cm` defaults to the map's when the map knows it. The pipeline reads
  /// `map` in place (a table is megabytes): it must outlive the pipeline.
  BallsightOmniPipeline(const YuvRange& ball_color, const GroundMap& map, BallOnFloor ball);

  /// The ball's centre in the robot frame (cm): the largest ball-coloured blob.
  std::optional<Vec2> locate_in_robot_cm(const cv::Mat& bgr) const;
  std::optional<Vec2> locate_cm(const cv::Mat& bgr, const Pose2D& robot_cm) const;

 private:
  ColorClassTable table_;
  const GroundMap& map_;
  BallOnFloor ball_;
  OmniBlobFinder finder_;
};

}  // namespace ballsight
