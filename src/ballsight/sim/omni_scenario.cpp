#include "ballsight/sim/omni_scenario.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/msl_field.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {

namespace {

OmniRigParams rig_params(const OmniScenarioOptions& options, std::mt19937_64& rng) {
  // Always draw all three so that overriding one does not change the rest of the scenario.
  const double tilt_deg = uniform(rng, 1.0, 2.0);
  const double tilt_azimuth_deg = uniform(rng, 0.0, 360.0);
  const double offset_px = uniform(rng, 3.0, 7.0);
  const double offset_angle = uniform(rng, 0.0, 2.0 * kPi);
  OmniRigParams rig;
  rig.tilt_deg = options.tilt_deg.value_or(tilt_deg);
  rig.tilt_azimuth_deg = options.tilt_azimuth_deg.value_or(tilt_azimuth_deg);
  rig.center_offset_px = options.center_offset_px.value_or(
      offset_px * Vec2(std::cos(offset_angle), std::sin(offset_angle)));
  rig = with_mirror(rig, options.mirror);
  rig.validate();
  return rig;
}

Pose2D random_robot_pose(const MslFieldSpec& field, std::mt19937_64& rng) {
  constexpr double kInside = 0.5;  // keep the robot this far inside the lines
  return {{uniform(rng, kInside, field.width_m - kInside),
           uniform(rng, kInside, field.length_m - kInside)},
          uniform(rng, -kPi, kPi)};
}

OmniBall random_ball(const OmniScenarioOptions& options, const MslField& field,
                     const Pose2D& robot_pose, std::mt19937_64& rng) {
  // A robot inside the lines always has carpet within reach in some direction, so this ends
  // quickly; the cap only guards the invariant.
  for (int attempt = 0; attempt < 10000; ++attempt) {
    const double distance = uniform(rng, options.ball_min_distance_m, options.ball_max_distance_m);
    const Vec2 p_in_robot = robot_point_from_bearing(uniform(rng, -180.0, 180.0), distance);
    const Vec2 p_in_field = field_from_robot_point(robot_pose, p_in_robot);
    if (field.on_carpet(p_in_field)) return {p_in_field, OmniBall{}.radius_m};
  }
  throw std::logic_error("omni scenario: no ball position on the carpet");
}

}  // namespace

void OmniScenarioOptions::validate() const {
  require(frames >= 1 && frames <= 10000, "scenario.frames", "must be in [1, 10000]");
  OmniRigParams rig;
  rig.tilt_deg = tilt_deg.value_or(rig.tilt_deg);
  rig.tilt_azimuth_deg = tilt_azimuth_deg.value_or(rig.tilt_azimuth_deg);
  rig.center_offset_px = center_offset_px.value_or(rig.center_offset_px);
  rig.validate();
  effects.validate();
  require(std::isfinite(ball_min_distance_m) && ball_min_distance_m >= 0.4,
          "scenario.ball_min_distance_m", "must be at least 0.4 m (clear of the robot's body)");
  require(std::isfinite(ball_max_distance_m) && ball_max_distance_m >= ball_min_distance_m &&
              ball_max_distance_m <= 10.0,
          "scenario.ball_max_distance_m", "must be in [ball_min_distance_m, 10] m");
}

std::vector<FloorMarker> calibration_markers(const Pose2D& robot_pose, const MarkerLayout& layout) {
  std::vector<FloorMarker> markers;
  for (const LayoutMarker& m : layout_markers(layout)) {
    markers.push_back({static_cast<int>(markers.size()),
                       field_from_robot_point(robot_pose, m.p_in_robot), m.radius_m});
  }
  return markers;
}

OmniScenario make_omni_scenario(const OmniScenarioOptions& options) {
  options.validate();
  std::mt19937_64 rig_rng(options.seed);
  OmniScenario scenario;
  scenario.rig = rig_params(options, rig_rng);
  const MslField field;
  for (int frame = 0; frame < options.frames; ++frame) {
    // An independent stream per frame, so that a frame does not depend on the frames before it.
    std::mt19937_64 rng(derive_seed(options.seed, static_cast<std::uint64_t>(frame)));
    OmniScene scene;
    scene.rig = scenario.rig;
    scene.field = field.spec();
    scene.robot_pose = random_robot_pose(scene.field, rng);
    scene.effects = options.effects;
    scene.noise_seed = rng();
    if (frame == 0 && options.calibration_frame) {
      scene.markers = calibration_markers(scene.robot_pose);
    } else {
      scene.ball = random_ball(options, field, scene.robot_pose, rng);
    }
    scenario.scenes.push_back(std::move(scene));
  }
  return scenario;
}

}  // namespace ballsight::sim
