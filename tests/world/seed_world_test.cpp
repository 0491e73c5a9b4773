#include "ballsight/world/seed_world.hpp"

#include <gtest/gtest.h>

#include "field_cameras.hpp"

namespace ballsight {
namespace {

PixelDetection seen(const FieldCamera& camera, const Vec3& p,
                    ObjectClass object = ObjectClass::ball) {
  PixelDetection d;
  d.object = object;
  d.center_px = *camera.pixel_from_field(p);
  d.area_px = 10.0;
  return d;
}

// The report's world: a ball seen by two cameras is merged (its two floor points lie within the
// fixed distance), two balls 50 cm apart are merged too (one "site" of the report), and a marker
// 34.5 cm up is placed on the floor far behind where it is.
TEST(SeedWorld, FixedDistanceMergeAndFloorPlane) {
  const std::vector<FieldCamera> cameras = test::corner_cameras();
  const Vec3 a(1.0, 1.0, 0.0335), b(1.5, 1.0, 0.0335), lone(-8.0, -3.0, 0.0335);
  const RobotModel robot;
  const Pose2D pose{Vec2(5.0, -2.0), 0.0};
  const Vec3 front(5.2, -2.0, robot.marker_height_m), back(4.8, -2.0, robot.marker_height_m);
  std::vector<std::optional<std::vector<PixelDetection>>> detections(4);
  detections[0] = {seen(cameras[0], a), seen(cameras[0], b),
                   seen(cameras[0], front, ObjectClass::robot_front_marker),
                   seen(cameras[0], back, ObjectClass::robot_back_marker)};
  detections[2] = {seen(cameras[2], a), seen(cameras[2], lone)};
  const WorldModel world = build_seed_world_model(cameras, detections, {});
  EXPECT_EQ(world.cameras, (std::vector<int>{0, 2}));
  ASSERT_EQ(world.balls.size(), 2u);
  EXPECT_EQ(world.sites.size(), 2u);
  ASSERT_TRUE(world.robot.has_value());
  // Floor points of the markers: more than a metre behind the robot, seen from 20 m at 5 m high.
  EXPECT_GT((world.robot->pose.position - pose.position).norm(), 1.0);
  EXPECT_NEAR(world.robot->pose.heading_rad, 0.0, 0.1);
}

}  // namespace
}  // namespace ballsight
