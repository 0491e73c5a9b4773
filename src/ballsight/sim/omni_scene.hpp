#pragma once
// What the omnidirectional simulator renders: a robot carrying an omni rig at a pose on an MSL
// field, an optional ball resting on the floor, flat floor markers, and the camera's effects.

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/image_effects.hpp"
#include "ballsight/sim/msl_field.hpp"

namespace ballsight::sim {

/// A ball resting on the floor (its centre is `radius_m` above the field point).
struct OmniBall {
  Vec2 position_in_field = Vec2::Zero();
  double radius_m = 0.11;  // FIFA size 5
};

/// A flat disc lying on the floor, as the calibration markers of the omnivision paper (Fig. 6).
struct FloorMarker {
  int id = 0;
  Vec2 position_in_field = Vec2::Zero();
  double radius_m = 0.05;
};

/// Colours of the scene's objects (BGR); the field has its own in MslFieldSpec.
struct OmniPalette {
  cv::Vec3b ball_bgr{0, 110, 255};          // orange
  cv::Vec3b marker_bgr{220, 40, 220};       // magenta: far from carpet, lines and ball
  cv::Vec3b robot_body_bgr{28, 28, 28};     // the robot's own body in the image centre
  cv::Vec3b background_bgr{150, 140, 130};  // whatever is seen above the horizon
};

struct OmniScene {
  OmniRigParams rig;
  MslFieldSpec field;
  Pose2D robot_pose;             // field_from_robot
  std::optional<OmniBall> ball;  // none: no ball in view
  std::vector<FloorMarker> markers;
  double robot_body_radius_m = 0.26;  // floor rays within this radius hit the robot's body
  OmniPalette palette;
  ImageEffects effects;
  std::uint64_t noise_seed = 0;  // seeds the sensor noise of `effects`

  /// Throws InputError naming the first invalid field (rig, field, pose, ball, markers[i], ...).
  void validate() const;
};

}  // namespace ballsight::sim
