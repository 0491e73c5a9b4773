#pragma once
// The truth behind a rendered omni frame: where everything is on the field and in the image, and
// the true pixel -> ground mapping (exactly OmniRig(rig).ground_from_pixel, plus a coarse sampled
// table of it). Written as JSON by omni_truth_json.hpp; documented in docs/sim-omni.md.

#include <cstdint>
#include <optional>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/image_effects.hpp"
#include "ballsight/sim/msl_field.hpp"
#include "ballsight/sim/omni_scene.hpp"

namespace ballsight::sim {

/// Where an object lies relative to the robot: ground distance and bearing (degrees,
/// counter-clockwise from the robot's forward axis, in [-180, 180)).
struct RobotRange {
  double distance_m = 0.0;
  double bearing_deg = 0.0;
};

struct OmniBallTruth {
  Vec2 position_in_field = Vec2::Zero();  // floor point under the ball's centre
  Vec2 position_in_robot = Vec2::Zero();
  double radius_m = 0.0;
  RobotRange range;
  std::optional<Vec2> center_px;  // projection of the ball's centre (nullopt: not in the mirror)
  /// Centroid of the ball's image, from its analytic outline (nullopt unless fully visible).
  std::optional<Vec2> silhouette_centroid_px;
  bool visible = false;  // the whole ball is imaged inside the mirror
};

struct OmniMarkerTruth {
  int id = 0;
  Vec2 position_in_field = Vec2::Zero();
  Vec2 position_in_robot = Vec2::Zero();
  double radius_m = 0.0;
  RobotRange range;
  std::optional<Vec2> pixel;  // projection of the disc's centre: the pixel a person would click
  std::optional<Vec2> silhouette_centroid_px;  // centroid of the disc's image outline
  bool visible = false;  // the whole disc is imaged inside the mirror and the ball hides no part
};

/// The true mapping sampled on an image-polar grid around the principal point (Algorithm 2 of
/// the omnivision paper): every `theta_step_deg` from 0 and every `radius_step_px` from one step
/// to the last step strictly inside the mirror circle.
struct OmniMappingSample {
  double theta_deg = 0.0;
  double radius_px = 0.0;
  std::optional<RobotRange> ground;  // nullopt: the pixel sees no floor (above the horizon)
};
struct OmniMappingTable {
  double theta_step_deg = 5.0;
  double radius_step_px = 10.0;
  std::vector<OmniMappingSample> samples;  // theta-major, radius ascending
};

struct OmniTruth {
  OmniRigParams rig;
  Vec2 image_center_px = Vec2::Zero();  // the true mirror centre (principal point)
  MslFieldSpec field;
  Pose2D robot_pose;  // field_from_robot
  double robot_body_radius_m = 0.0;
  ImageEffects effects;
  std::uint64_t noise_seed = 0;
  std::optional<OmniBallTruth> ball;
  std::vector<OmniMarkerTruth> markers;
  OmniMappingTable mapping;
};

/// The truth of `scene` as imaged by `rig` (which must be built from scene.rig).
OmniTruth make_omni_truth(const OmniScene& scene, const OmniRig& rig);

/// Samples rig.ground_from_pixel on the polar grid.
OmniMappingTable sample_omni_mapping(const OmniRig& rig, double theta_step_deg = 5.0,
                                     double radius_step_px = 10.0);

/// Ground distance and bearing of a robot-frame floor point.
RobotRange robot_range(const Vec2& p_in_robot);

}  // namespace ballsight::sim
