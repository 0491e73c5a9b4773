#pragma once
// What the court cameras see at one moment, in the field frame: the balls (each fused over the
// cameras that saw it), the collection sites they form, the obstacles, the robot's pose and which
// cameras contributed. The value `court run` prints and the navigation service will publish.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/world/collection_sites.hpp"
#include "ballsight/world/robot_pose.hpp"

namespace ballsight {

struct FusedBall {
  Vec2 position_m = Vec2::Zero();                           // centre, field frame
  Eigen::Matrix2d covariance_m2 = Eigen::Matrix2d::Zero();  // expected error (0: not estimated)
  std::vector<int> cameras;                                 // cameras that saw it, ascending
};

/// Something standing on the court that is not a ball, the robot or the net (a person, a bag), as
/// two or more cameras see it (world/floor_obstacles.hpp).
struct FloorObstacle {
  Vec2 center_m = Vec2::Zero();  // the footprint's centre
  double radius_m = 0.0;         // the smallest circle about the centre that holds the footprint
  std::vector<Vec2> outline_m;   // the footprint's convex outline, counter-clockwise
  std::vector<int> cameras;      // cameras that saw it, ascending
};

struct WorldModel {
  std::vector<FusedBall> balls;
  std::vector<FloorObstacle> obstacles;
  std::vector<CollectionSite> sites;  // indices into balls
  std::optional<RobotPoseEstimate> robot;
  std::vector<int> cameras;  // cameras whose frames went into this model, ascending
  /// UTC, when the oldest frame it was made from was captured (0: not known).
  std::int64_t capture_time_ns = 0;
};

/// Throws InputError naming `where` unless there is one detection list per camera.
void require_list_per_camera(std::size_t cameras, std::size_t lists, const char* where);

}  // namespace ballsight
