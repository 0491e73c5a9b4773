#include "ballsight/world/ball_on_floor.hpp"

#include <gtest/gtest.h>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TEST(BallOnFloor, RecoversTheCentreFromTheFloorHitBehindIt) {
  OmniRigParams params;
  params.tilt_deg = 1.5;
  params.tilt_azimuth_deg = 40.0;
  const OmniRig rig(params);
  const BallOnFloor ball{11.0, rig.robot_from_camera().translation.z() * 100.0};
  for (double bearing = 0.0; bearing < 360.0; bearing += 30.0) {
    for (double distance_m : {0.8, 1.2, 2.85, 5.0}) {
      const Vec2 c = robot_point_from_bearing(bearing, distance_m);
      const auto pixel = rig.pixel_from_point({c.x(), c.y(), 0.11});
      ASSERT_TRUE(pixel);
      const auto floor_hit_m = rig.ground_from_pixel(*pixel);
      ASSERT_TRUE(floor_hit_m);
      EXPECT_GT(floor_hit_m->norm(), distance_m + 0.02);  // the naive read overshoots
      // The viewpoint sits above the robot origin, so the correction is exact up to rounding.
      EXPECT_NEAR((ball_center_from_floor_hit_cm(*floor_hit_m * 100.0, ball) - c * 100.0).norm(),
                  0.0, 1e-6);
    }
  }
}

TEST(BallOnFloor, NeedsAKnownViewpointHeight) {
  EXPECT_THROW((BallOnFloor{11.0, 0.0}).validate(), InputError);
  EXPECT_THROW((BallOnFloor{-1.0, 60.0}).validate(), InputError);
}

}  // namespace
}  // namespace ballsight
