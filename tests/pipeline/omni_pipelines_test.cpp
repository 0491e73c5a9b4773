#include "ballsight/pipeline/omni_pipelines.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/sim/omni_renderer.hpp"

namespace ballsight {
namespace {

const Vec2 kConfiguredCenter(319.5, 239.5);

sim::OmniScene ball_scene(const OmniRigParams& rig, const Vec2& ball_in_robot_m) {
  sim::OmniScene scene;
  scene.rig = rig;
  scene.robot_pose = {{3.0, 5.0}, 0.4};
  scene.ball = sim::OmniBall{field_from_robot_point(scene.robot_pose, ball_in_robot_m)};
  scene.effects.noise_sigma = 3.0;
  return scene;
}

GroundMapInfo map_info() {
  GroundMapInfo info;
  info.min_radius_px = 40.0;
  info.max_radius_px = 235.0;
  info.method = "truth";
  return info;
}

// With the true mapping, ballsight's pipeline puts the ball's centre within a centimetre or two
// out to 4 m on a misaligned rig: whole blob, silhouette rays, ball-radius correction.
TEST(OmniPipelines, BallsightPlacesTheBallCentreWithTheTrueMapping) {
  OmniRigParams rig;
  rig.tilt_deg = 1.5;
  rig.tilt_azimuth_deg = 60.0;
  rig.center_offset_px = {5.0, -3.0};
  const GroundMap map = ground_map_from_rig(OmniRig(rig), map_info());
  const BallsightOmniPipeline pipeline(yuv_range_around(sim::OmniPalette{}.ball_bgr), map,
                                       BallOnFloor{});
  for (const double distance_m : {1.0, 2.0, 3.0, 4.0}) {
    for (const double bearing_deg : {0.0, 75.0, 200.0, 310.0}) {
      SCOPED_TRACE(std::to_string(distance_m) + " m, " + std::to_string(bearing_deg) + " deg");
      const Vec2 truth_m = robot_point_from_bearing(bearing_deg, distance_m);
      const sim::OmniScene scene = ball_scene(rig, truth_m);
      const std::optional<Vec2> found =
          pipeline.locate_in_robot_cm(sim::render_omni_scene(scene).bgr);
      ASSERT_TRUE(found);
      EXPECT_LT((*found - 100.0 * truth_m).norm(), 2.0 * distance_m);
    }
  }
}

// The paper's pipeline on an ideal rig with the true radial distance. Algorithm 3 as printed
// keeps the first ball pixel of the *last* ray (counter-clockwise) that meets the ball: a ray
// along the ball's side, entering its blob near the centre's radius. Its floor point lies behind
// the ball, up to where the ray through the ball's centre meets the floor (D h / (h - R)), and
// its bearing is turned counter-clockwise by up to half the ball's angular width.
TEST(OmniPipelines, PaperPipelineReadsALateSideOfTheBall) {
  const OmniRigParams rig;
  const OmniRig truth(rig);
  const PaperOmniPipeline pipeline(
      yuv_range_around(sim::OmniPalette{}.ball_bgr), kConfiguredCenter,
      [&](double theta_deg, double radius_px) -> std::optional<double> {
        const auto p = truth.ground_from_pixel(
            pixel_from_image_polar({theta_deg, radius_px}, kConfiguredCenter));
        if (!p) return std::nullopt;
        return 100.0 * p->norm();
      });
  for (const double distance_m : {1.2, 2.0, 2.85}) {
    SCOPED_TRACE(std::to_string(distance_m) + " m");
    const Vec2 truth_m = robot_point_from_bearing(30.0, distance_m);
    const sim::OmniScene scene = ball_scene(rig, truth_m);
    const Pose2D robot_cm{100.0 * scene.robot_pose.position, scene.robot_pose.heading_rad};
    const std::optional<Vec2> field_cm =
        pipeline.locate_cm(sim::render_omni_scene(scene).bgr, robot_cm);
    ASSERT_TRUE(field_cm);
    const Vec2 in_robot = robot_from_field_point(robot_cm, *field_cm);
    const double h = 100.0 * rig.height_m, r = 11.0, d = 100.0 * distance_m;
    EXPECT_GT(in_robot.norm(), d);
    EXPECT_LT(in_robot.norm(), d * h / (h - r) + 2.0);
    const double half_width_deg = deg_from_rad(std::asin(r / d));
    EXPECT_GT(polar_from_cartesian(in_robot).theta_deg, 30.0);
    EXPECT_LT(polar_from_cartesian(in_robot).theta_deg, 30.0 + half_width_deg);
  }
}

}  // namespace
}  // namespace ballsight
