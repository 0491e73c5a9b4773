#pragma once
// Pictures of the court evaluation: a camera's view with each method's detections overlaid, and
// a top-down map of the court with the true balls and robot against each method's estimates
// (eval/plot_inputs.hpp reads the evaluation's truth and mistakes into TrueBallMark and
// MistakeMark).

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/viz/court_map.hpp"
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

/// A true ball on the map: grey when no camera sees it.
struct TrueBallMark {
  Vec2 position_m = Vec2::Zero();
  bool seen = true;
};

/// A ball a method got wrong, marked with a letter: 'M' missed (the true position), 'D'
/// duplicate or 'F' false positive (the estimate's).
struct MistakeMark {
  Vec2 position_m = Vec2::Zero();
  char letter = 'M';
};

/// One method's world model on the map, with the balls it got wrong marked.
struct WorldLayer {
  std::string label;
  cv::Scalar colour;
  WorldModel world;
  std::vector<MistakeMark> mistakes;
};

/// Top-down map of the court area (the floor's run-off and a margin): lines, cameras, true balls
/// (grey: seen by no camera) and the true robot, each layer's balls, collection sites and robot
/// pose, its mistakes (magenta rings with their letters), with a five times larger inset of the
/// 3 x 2 m around the robot below it; `pixels_per_m` sets the scale.
cv::Mat draw_field_map(const CourtFloor& floor, const std::vector<Vec3>& cameras,
                       const std::vector<TrueBallMark>& truth, const Pose2D& robot_truth,
                       const std::vector<WorldLayer>& layers, const std::string& title,
                       double pixels_per_m = 40.0);

}  // namespace ballsight
