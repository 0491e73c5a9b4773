#pragma once
// ballsight's world model from the court cameras' detections: every detection placed on the plane
// of its object's centre with its expected error, the robot's pose from its markers, ball
// detections the robot's body may cut into made less certain, then the balls fused across cameras
// by their expected errors, groups of touching balls refitted to their observations and then to
// their blobs' pixels (pixel_cluster_fit.hpp), checked against the cameras that missed them
// (ball_support.hpp) and grouped into collection sites; and what else stands on the floor, from
// the cameras' views of what is not the empty court (floor_obstacles.hpp).

#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/field_rect.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/world/ball_support.hpp"
#include "ballsight/world/cluster_refinement.hpp"
#include "ballsight/world/field_observation.hpp"
#include "ballsight/world/floor_obstacles.hpp"
#include "ballsight/world/observation_fusion.hpp"
#include "ballsight/world/pixel_cluster_fit.hpp"
#include "ballsight/world/robot_pose.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

struct CourtWorldOptions {
  double ball_radius_m = 0.0335;  // a ball's centre is this high
  RobotModel robot;
  ObservationNoise noise;
  FusionOptions fusion;
  ClusterOptions clusters;
  PixelFitOptions pixel_fit;
  BallSupportOptions support;
  FloorObstacleOptions obstacles;
  double collector_width_m = 0.70;               // the report's collector (section 7.8)
  FieldRect area{{-19.5, -10.5}, {19.5, 10.5}};  // observations elsewhere are dropped

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// How high an object's centre is above the floor: a ball's radius, the robot markers' height, 0
/// for an obstacle's view (where it stands).
double object_center_height_m(ObjectClass object, const CourtWorldOptions& options);

/// Detections of one frame set: `detections[i]` from `cameras[i]`, nullopt for a camera whose
/// frame is missing (it is then not among the model's cameras).
WorldModel build_world_model(
    const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections,
    const CourtWorldOptions& options);

/// The robot's body as seen by `camera`: the convex outline of its box's projected corners
/// (empty when a corner does not project).
std::vector<cv::Point2f> robot_outline_px(const FieldCamera& camera, const Pose2D& robot_pose,
                                          const RobotModel& robot);

}  // namespace ballsight
