#pragma once
// Deterministic omni scenarios: one misaligned rig (as the omnivision paper's robot), a robot at
// random poses on the field and a ball 0.5-5 m away, optionally preceded by a calibration frame
// showing the paper's marker layout. Everything is drawn from std::mt19937_64 streams seeded from
// `seed` (one for the rig, one per frame; portable: no standard library distributions).

#include <cstdint>
#include <optional>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/core/marker_layout.hpp"
#include "ballsight/sim/image_effects.hpp"
#include "ballsight/sim/omni_scene.hpp"

namespace ballsight::sim {

struct OmniScenarioOptions {
  std::uint64_t seed = 1;
  int frames = 4;
  // Misalignment of the rig; unset values are drawn from the seed: tilt 1-2 deg towards a random
  // bearing, principal point 3-7 px off the image centre in a random direction.
  std::optional<double> tilt_deg;
  std::optional<double> tilt_azimuth_deg;
  std::optional<Vec2> center_offset_px;
  MirrorKind mirror = MirrorKind::kUnified;  // the rig's mirror: its default_mirror()
  ImageEffects effects;
  bool calibration_frame = true;  // frame 0: the marker layout around the robot, no ball
  double ball_min_distance_m = 0.5;
  double ball_max_distance_m = 5.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct OmniScenario {
  OmniRigParams rig;  // shared by every scene: one camera on one robot
  std::vector<OmniScene> scenes;
};

OmniScenario make_omni_scenario(const OmniScenarioOptions& options);

/// The layout's markers around a robot at `robot_pose`, on the field; id = the layout's index.
std::vector<FloorMarker> calibration_markers(const Pose2D& robot_pose,
                                             const MarkerLayout& layout = {});

}  // namespace ballsight::sim
