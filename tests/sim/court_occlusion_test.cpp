#include <gtest/gtest.h>

#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/court_truth.hpp"
#include "sim/court_test_support.hpp"

namespace ballsight::sim {
namespace {

using test_support::clean_scenario;
using test_support::render_in_all_cameras;
using test_support::shared_court;

/// Pixels of the id buffer showing object `index`.
int pixels_showing(const CourtRender& render, int index) {
  return cv::countNonZero(render.object_ids == index);
}

TEST(CourtOcclusion, BallRightBehindTheRobotIsHiddenFromThatCameraOnly) {
  const test_support::CourtFixture& court = shared_court();
  CourtScene scene;
  // On camera 0's side of the net and far enough from it that the cameras on the other side see
  // the box and the ball over the net; turned so that no camera sees one marker behind the other.
  scene.robot.pose = {{8.0, 1.0}, 1.2};
  scene.effects.noise_sigma = 0.0;
  // On camera 0's line of sight through the middle of the box, where it comes down to ball
  // height behind the box.
  const Vec3 eye = court.rig.cameras[0].center_in_field();
  const Vec3 through(8.0, 1.0, 0.27);
  const Vec3 d = through - eye;
  const double t = (kTennisBallRadiusM - eye.z()) / d.z();
  const Vec3 ball = eye + t * d;
  const Vec2 in_robot = scene.robot.pose.field_from_robot().inverse() * ball.head<2>();
  ASSERT_TRUE(std::abs(in_robot.x()) > scene.robot.length_m / 2 + 0.04 ||
              std::abs(in_robot.y()) > scene.robot.width_m / 2 + 0.04)
      << "the ball must stand clear of the box: " << in_robot.transpose();
  scene.balls.push_back({ObjectKind::tennis_ball, 0, ball, kTennisBallRadiusM, kTennisBallBgr});

  const auto rendered = render_in_all_cameras(scene);
  const SphereTruth& truth = rendered.truth[0];
  EXPECT_TRUE(truth.views[0].in_image);
  EXPECT_FALSE(truth.views[0].visible);
  EXPECT_LT(truth.views[0].visible_fraction, 0.05);
  EXPECT_EQ(pixels_showing(rendered.renders[0], 0), 0);
  // The camera at the opposite corner sees it whole.
  EXPECT_TRUE(truth.views[2].visible);
  EXPECT_DOUBLE_EQ(truth.views[2].visible_fraction, 1.0);
  EXPECT_GT(pixels_showing(rendered.renders[2], 0), 0);
  // The robot's markers sit on top of the box: nothing hides them.
  for (size_t c = 0; c < 4; ++c) {
    EXPECT_DOUBLE_EQ(rendered.truth[1].views[c].visible_fraction, 1.0) << "camera " << c;
    EXPECT_DOUBLE_EQ(rendered.truth[2].views[c].visible_fraction, 1.0) << "camera " << c;
  }
}

// A bottle stands up like the robot: it hides a ball right behind it from one camera, and is
// seen by all four; a leaf lies flat and hides nothing, but colours the floor.
TEST(CourtOcclusion, ABottleHidesTheBallBehindItALeafColoursTheFloor) {
  const test_support::CourtFixture& court = shared_court();
  CourtScene scene;
  scene.robot.pose = {{-8.0, 1.0}, 0.3};
  scene.effects.noise_sigma = 0.0;
  FloorBottle bottle;
  bottle.center_in_field = Vec2(5.0, -2.0);
  scene.bottles.push_back(bottle);
  const Vec3 eye = court.rig.cameras[0].center_in_field();
  const Vec3 d = Vec3(5.0, -2.0, 0.12) - eye;
  const Vec3 ball = eye + (kTennisBallRadiusM - eye.z()) / d.z() * d;
  ASSERT_GT((ball.head<2>() - bottle.center_in_field).norm(),
            bottle.radius_m + kTennisBallRadiusM + 0.01);
  scene.balls.push_back({ObjectKind::tennis_ball, 0, ball, kTennisBallRadiusM, kTennisBallBgr});

  const auto rendered = render_in_all_cameras(scene);
  EXPECT_LT(rendered.truth[0].views[0].visible_fraction, 0.5);
  EXPECT_DOUBLE_EQ(rendered.truth[0].views[2].visible_fraction, 1.0);
  const int bottle_index = static_cast<int>(scene.spheres().size()) + 1;
  for (size_t c = 0; c < 4; ++c)
    EXPECT_GT(pixels_showing(rendered.renders[c], bottle_index), 4) << "camera " << c;

  FloorLeaf leaf;
  leaf.center_in_field = Vec2(3.0, 3.0);
  leaf.half_length_m = 0.09;
  leaf.half_width_m = 0.05;
  scene.leaves.push_back(leaf);
  const cv::Mat with_leaf = court.renderers[0].render(scene, 0).bgr;
  cv::Mat differs;
  cv::compare(with_leaf, rendered.renders[0].bgr, differs, cv::CMP_NE);
  EXPECT_GT(cv::countNonZero(differs.reshape(1)), 10);
  EXPECT_EQ(cv::countNonZero(court.renderers[0].render(scene, 0).object_ids !=
                             rendered.renders[0].object_ids),
            0);
}

TEST(CourtOcclusion, TouchingBallsHideEachOtherOnlyPartly) {
  CourtScene scene;
  scene.robot.pose = {{-8.0, -3.0}, 0.0};
  const Vec3 eye = shared_court().rig.cameras[1].center_in_field();
  // Two touching balls in a row along camera 1's viewing direction, far away on its side of the
  // net.
  const Vec3 front(3.0, 2.0, kTennisBallRadiusM);
  Vec3 away = front - eye;
  away.z() = 0.0;
  const Vec3 back = front + away.normalized() * (2 * kTennisBallRadiusM + 0.002);
  scene.balls.push_back({ObjectKind::tennis_ball, 0, front, kTennisBallRadiusM, kTennisBallBgr});
  scene.balls.push_back({ObjectKind::tennis_ball, 1, back, kTennisBallRadiusM, kTennisBallBgr});
  const auto rendered = render_in_all_cameras(scene);
  EXPECT_DOUBLE_EQ(rendered.truth[0].views[1].visible_fraction, 1.0);
  const double hidden = rendered.truth[1].views[1].visible_fraction;
  EXPECT_GT(hidden, 0.05);
  EXPECT_LT(hidden, 0.9);
}

TEST(CourtOcclusion, ScenariosHideSomeBallsBehindTheRobotInSomeViews) {
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    SCOPED_TRACE("scene seed " + std::to_string(seed));
    const auto rendered =
        render_in_all_cameras(make_court_scene(TennisCourtSpec{}, clean_scenario(), seed));
    int hidden_here_seen_there = 0;
    for (const SphereTruth& t : rendered.truth) {
      bool hidden = false, seen = false;
      for (const SphereViewTruth& v : t.views) {
        hidden = hidden || (v.in_image && !v.visible);
        seen = seen || v.visible;
      }
      if (t.sphere.kind == ObjectKind::tennis_ball && hidden && seen) ++hidden_here_seen_there;
    }
    EXPECT_GE(hidden_here_seen_there, 1);
  }
}

}  // namespace
}  // namespace ballsight::sim
