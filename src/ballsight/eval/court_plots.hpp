#pragma once
// Pictures of the court evaluation: a camera's view with each method's detections overlaid, and
// a top-down map of the court with the true balls and robot against each method's estimates.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/eval/court_metrics.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

/// One method's detections in one view, drawn in one colour.
struct DetectionLayer {
  std::string label;
  cv::Scalar colour;
  std::vector<PixelDetection> detections;
};

/// The frame with the true balls' pixels (white rings), each layer's detections (balls:
/// circles, markers: squares), the true balls ballsight missed (`missed_px`, magenta rings and
/// "M"), a title and a legend.
cv::Mat draw_detection_overlay(const cv::Mat& frame, const std::vector<Vec2>& truth_px,
                               const std::vector<DetectionLayer>& layers,
                               const std::vector<Vec2>& missed_px, const std::string& title);

/// One method's world model on the map, with the balls it got wrong (court_metrics.hpp) marked.
struct WorldLayer {
  std::string label;
  cv::Scalar colour;
  WorldModel world;
  std::vector<BallMistake> mistakes;
};

/// Top-down map of the court area: lines, cameras, true balls (grey: seen by no camera) and the
/// true robot, each layer's balls, collection sites and robot pose, its mistakes (magenta rings
/// with M: missed, D: duplicate, F: false positive), with a five times larger inset
/// of the 3 x 2 m around the robot below it; `pixels_per_m` sets the scale.
cv::Mat draw_field_map(const sim::TennisCourtSpec& court, const std::vector<Vec3>& cameras,
                       const std::vector<TruthBall>& truth, const Pose2D& robot_truth,
                       const std::vector<WorldLayer>& layers, const std::string& title,
                       double pixels_per_m = 40.0);

}  // namespace ballsight
