// `omni-node --sim` as a separate process on loopback: the ball it writes robot-relative is the
// simulated ball, and with a robot pose coming in it writes the ball on the field through that
// pose.

#include <gtest/gtest.h>

#include <map>

#include "ballsight/core/child_process.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/dds/court_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/sim/omni_scenario.hpp"
#include "dds_domain.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using namespace std::chrono_literals;

TEST(OmniNode, WritesTheSimulatedBallAndPlacesItOnTheFieldWithTheRobotPose) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  const dds::Participant participant(domain);
  dds::Reader<dds::PointStampedMsg> ball(participant, "ball");
  dds::Reader<dds::PointStampedMsg> ball_field(participant, "ball_field");
  dds::Writer<dds::PoseStampedMsg> robot_pose(participant, "robot_pose");
  constexpr int kScenes = 5;
  constexpr std::int64_t kPeriodNs = 100'000'000;  // --rate 10
  ChildProcess node(
      BALLSIGHT_CLI,
      {"omni-node", "--sim", "--seed", "7", "--scenes", std::to_string(kScenes), "--rate", "10",
       "--loopback", "--domain", std::to_string(*domain.domain), "--namespace", domain.ns},
      dir / "omni.log");
  sim::OmniScenarioOptions options;
  options.seed = 7;
  options.frames = kScenes;
  options.calibration_frame = false;
  const sim::OmniScenario scenario = sim::make_omni_scenario(options);

  const Pose2D pose{{1.0, 2.0}, std::numbers::pi / 2.0};  // the robot's localisation says
  std::map<std::int64_t, Vec2> in_robot;                  // by capture time
  std::map<std::int64_t, Vec2> in_field;
  std::string field_frame;
  const auto until = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < until &&
         (in_robot.size() < 10 || in_field.size() < 5)) {
    dds::MessageArena arena;
    dds::PoseStampedMsg message{};
    message.header = dds::header_message(utc_now_ns(), "field", arena);
    message.pose = dds::pose_message(pose);
    robot_pose.write(message);
    ball.wait(50ms);
    ball.take([&](const dds::PointStampedMsg& m) {
      EXPECT_EQ(std::string(m.header.frame_id), "base_link");
      EXPECT_NEAR(m.point.z, 0.11, 1e-12) << "the ball's centre height";
      in_robot[dds::stamp_ns(m.header)] = {m.point.x, m.point.y};
    });
    ball_field.take([&](const dds::PointStampedMsg& m) {
      field_frame = m.header.frame_id;
      in_field[dds::stamp_ns(m.header)] = {m.point.x, m.point.y};
    });
  }
  ASSERT_GE(in_robot.size(), 10u) << node.log_text();
  ASSERT_GE(in_field.size(), 5u) << node.log_text();
  EXPECT_EQ(field_frame, "field");

  double worst_m = 0.0;
  for (const auto& [stamp, p] : in_robot) {
    ASSERT_EQ(stamp % kPeriodNs, 0) << "frames stamped at whole ticks";
    const sim::OmniScene& scene =
        scenario.scenes[static_cast<std::size_t>(stamp / kPeriodNs % kScenes)];
    const Vec2 truth = robot_from_field_point(scene.robot_pose, scene.ball->position_in_field);
    worst_m = std::max(worst_m, (p - truth).norm() / std::max(1.0, truth.norm()));
  }
  EXPECT_LT(worst_m, 0.02) << "the ball within 2 cm per metre of distance";
  int compared = 0;
  for (const auto& [stamp, p] : in_field) {
    if (!in_robot.contains(stamp)) continue;  // its `ball` not taken before the loop ended
    EXPECT_LT((p - field_from_robot_point(pose, in_robot[stamp])).norm(), 1e-9);
    ++compared;
  }
  EXPECT_GE(compared, 4);
}

TEST(OmniNode, RefusesAMissingCamera) {
  const test::TempDir dir;
  ChildProcess node(BALLSIGHT_CLI,
                    {"omni-node", "--camera", (dir / "none.png").string(), "--lut", "t"},
                    dir / "omni.log");
  EXPECT_NE(node.wait(30s), 0);
  EXPECT_NE(node.log_text().find("--camera"), std::string::npos) << node.log_text();
}

}  // namespace
}  // namespace ballsight
