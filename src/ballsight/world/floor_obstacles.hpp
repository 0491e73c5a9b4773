#pragma once
// Where obstacles stand, from the cameras' views of what is not the empty court
// (detect/court_foreground.hpp): a grid of floor cells, each looked at by every camera that sees
// it (not through the net). A cell is occupied when its floor point shows changed pixels in two or
// more cameras and in all but at most one of those that see it: an object standing there covers its
// floor point in every view, while the floor behind an object (its "shadow" in one camera's view)
// is covered in that camera only. Only cells near the feet of the views are looked at (the lowest
// changed pixel of each column, where the object meets the floor): a few thousand projections per
// frame set.
//
// Cells at the robot's body and at the balls are left out (they are foreground too); the occupied
// cells, put together where they touch, are the obstacles.

#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/field_rect.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/world/net_panel.hpp"
#include "ballsight/world/robot_pose.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

struct FloorObstacleOptions {
  double cell_m = 0.1;
  double search_m = 0.8;        // cells this near a view's foot are looked at
  int min_cells = 4;            // smaller groups are not obstacles (a ball cluster's corner)
  double robot_margin_m = 0.4;  // around the robot's body, nothing is an obstacle
  double ball_margin_m = 0.12;  // around a ball's centre, nothing is an obstacle
  int column_step_px = 2;       // feet are taken every this many columns of a view at least,
  int max_feet_per_view = 16;   // and this many at most
  double ball_feet_m = 0.3;     // a foot this near a ball is the ball's own view's
  int foot_rise_px = 2;         // a floor point counts as covered this far below a view
  /// The court's net: a camera that looks at a floor point through it does not see what stands
  /// there (the net, part of the empty court, is in front of its foot).
  std::optional<NetPanel> net;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The obstacles in `area` from the obstacle views among `detections` (one list per camera,
/// nullopt: no frame), the robot at `robot` (if seen) and the `balls` left out.
std::vector<FloorObstacle> locate_floor_obstacles(
    const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections,
    const std::optional<Pose2D>& robot, const RobotModel& robot_model,
    const std::vector<FusedBall>& balls, const FieldRect& area,
    const FloorObstacleOptions& options);

}  // namespace ballsight
