#pragma once
// A fused ball must be consistent with every camera that missed it: a camera that had a frame
// and should have seen the ball (centre in its image, large enough to detect, not behind the
// robot's body or the net, not behind a nearer ball, and no detection of its own right there)
// testifies against it. A ball is kept when fewer cameras testify against it than saw it; so a ball
// seen by one camera only is kept exactly when every other camera's miss is explained (e.g. the
// robot hides it from them), and the leftovers of a wrongly split blob or a reference ball mistaken
// for a ball by one distant camera are dropped.

#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/world/net_panel.hpp"
#include "ballsight/world/robot_pose.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

struct BallSupportOptions {
  double min_radius_px = 1.0;      // smaller in a camera: it need not have seen the ball
  double robot_margin_m = 0.03;    // the robot's body, grown by this, hides what is behind it
  double same_place_radii = 0.6;   // a detection this many ball radii from the ball: seen there
  double min_same_place_px = 1.0;  // ... and at least this many pixels
  std::optional<NetPanel> net;     // the court's net hides what is behind it

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Why a camera did not report a ball (or that it should have).
enum class MissReason {
  out_of_view,
  too_small,
  behind_robot,
  behind_net,
  behind_ball,
  detected_there,
  unexplained
};

/// Why `camera` has no observation of the ball at `center_in_field` (radius `radius_m`) among
/// `balls` (the fused balls, nearer ones may hide it; `self` is its own index, skipped) and the
/// camera's `detections`.
MissReason explain_miss(const FieldCamera& camera, const Vec3& center_in_field, double radius_m,
                        const std::vector<FusedBall>& balls, std::size_t self,
                        const std::vector<PixelDetection>& detections,
                        const std::optional<Pose2D>& robot_pose, const RobotModel& robot,
                        const BallSupportOptions& options);

/// For each ball: kept (true) or dropped. `detections[c]` is nullopt for a camera without a frame.
std::vector<bool> supported_balls(
    const std::vector<FusedBall>& balls, const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double radius_m,
    const std::optional<Pose2D>& robot_pose, const RobotModel& robot,
    const BallSupportOptions& options);

}  // namespace ballsight
