#include "ballsight/world/ball_support.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/angle.hpp"
#include "field_cameras.hpp"

namespace ballsight {
namespace {

constexpr double kRadius = 0.0335;

PixelDetection ball_pixel(const FieldCamera& camera, const Vec3& p) {
  PixelDetection d;
  d.center_px = *camera.pixel_from_field(p);
  d.radius_px = 1.5;
  return d;
}

// A ball right behind the robot as seen by cameras 0 and 1 is seen only by 2 and 3: kept. The
// same ball with the robot elsewhere is contradicted by 0 and 1: dropped.
TEST(BallSupport, ABallTheRobotHidesFromSomeCamerasIsKept) {
  const std::vector<FieldCamera> cameras = test::corner_cameras();
  const Vec3 ball(0.0, 0.0, kRadius);
  // The robot between the ball and the +x cameras (0 at +x+y, 1 at +x-y), its long side facing
  // them.
  const Pose2D robot{Vec2(0.40, 0.0), kPi / 2};
  std::vector<std::optional<std::vector<PixelDetection>>> detections(4,
                                                                     std::vector<PixelDetection>{});
  detections[2]->push_back(ball_pixel(cameras[2], ball));
  detections[3]->push_back(ball_pixel(cameras[3], ball));
  FusedBall fused;
  fused.position_m = ball.head<2>();
  fused.cameras = {2, 3};
  const RobotModel model;
  const BallSupportOptions options;
  for (int c : {0, 1})
    EXPECT_EQ(explain_miss(cameras[static_cast<size_t>(c)], ball, kRadius, {fused}, 0,
                           *detections[static_cast<size_t>(c)], robot, model, options),
              MissReason::behind_robot);
  EXPECT_TRUE(supported_balls({fused}, cameras, detections, kRadius, robot, model, options)[0]);
  const Pose2D elsewhere{Vec2(-5.0, 3.0), 0.0};
  EXPECT_FALSE(
      supported_balls({fused}, cameras, detections, kRadius, elsewhere, model, options)[0]);
}

// One distant camera's blob where three cameras that see the place clearly saw nothing (a reference
// ball mistaken for a tennis ball): dropped; a camera without a frame does not testify.
TEST(BallSupport, AOneCameraBallTheOthersContradictIsDropped) {
  const std::vector<FieldCamera> cameras = test::corner_cameras();
  const Vec3 place(-6.0, 0.0, kRadius);
  FusedBall fused;
  fused.position_m = place.head<2>();
  fused.cameras = {0};
  std::vector<std::optional<std::vector<PixelDetection>>> detections(4,
                                                                     std::vector<PixelDetection>{});
  detections[0]->push_back(ball_pixel(cameras[0], place));
  EXPECT_EQ(explain_miss(cameras[2], place, kRadius, {fused}, 0, {}, std::nullopt, {}, {}),
            MissReason::unexplained);
  EXPECT_FALSE(supported_balls({fused}, cameras, detections, kRadius, std::nullopt, {}, {})[0]);
  detections[1] = detections[2] = detections[3] = std::nullopt;
  EXPECT_TRUE(supported_balls({fused}, cameras, detections, kRadius, std::nullopt, {}, {})[0]);
}

// A ball hidden behind a nearer ball, or inside a blob the camera did report, is explained.
TEST(BallSupport, NeighboursAndMergedBlobsExplainAMiss) {
  const FieldCamera camera = test::corner_cameras()[0];
  const Vec3 far_ball(0.0, 0.0, kRadius);
  const Vec2 toward = (camera.center_in_field().head<2>() - far_ball.head<2>()).normalized();
  FusedBall near_ball;
  near_ball.position_m = far_ball.head<2>() + 0.068 * toward;
  EXPECT_EQ(explain_miss(camera, far_ball, kRadius, {near_ball}, 99, {}, std::nullopt, {}, {}),
            MissReason::behind_ball);
  PixelDetection merged = ball_pixel(camera, far_ball);
  merged.center_px += Vec2(1.2, 0.0);
  merged.radius_px = 2.0;
  EXPECT_EQ(explain_miss(camera, far_ball, kRadius, {}, 0, {merged}, std::nullopt, {}, {}),
            MissReason::detected_there);
}

}  // namespace
}  // namespace ballsight
