#include "ballsight/dds/court_messages.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ballsight/dds/topic_io.hpp"
#include "dds_domain.hpp"

namespace ballsight::dds {
namespace {

// The bytes of PoseStamped{stamp 1700000000 s + 500 ns, frame "court", x 1.5, y 2.25, w 1} on the
// wire, as the research note worked them out by hand (net-web.md §1, experiment 4) and a Fast DDS
// 2.9.1 reader decoded them: encapsulation CDR_LE, then XCDR1 with doubles aligned to 8 from the
// end of the 4-byte encapsulation header, the string's length counting its NUL.
TEST(CourtMessages, PoseStampedCrossesTheWireAsTheGoldenBytes) {
  const std::vector<std::uint8_t> golden{
      0x00, 0x01, 0x00, 0x00,                                     // CDR_LE
      0x00, 0xf1, 0x53, 0x65, 0xf4, 0x01, 0x00, 0x00,             // sec, nanosec
      0x06, 0x00, 0x00, 0x00, 'c',  'o',  'u',  'r',  't', 0x00,  // frame_id
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00,                         // padding
      0,    0,    0,    0,    0,    0,    0xf8, 0x3f, 0,   0,    0, 0, 0, 0, 0x02, 0x40,  // x, y
      0,    0,    0,    0,    0,    0,    0,    0,    0,   0,    0, 0, 0, 0, 0,    0,     // z, qx
      0,    0,    0,    0,    0,    0,    0,    0,    0,   0,    0, 0, 0, 0, 0,    0,     // qy, qz
      0,    0,    0,    0,    0,    0,    0xf0, 0x3f};                                    // qw
  const Participant participant(test::test_domain());
  Writer<PoseStampedMsg> writer(participant, "robot_pose");
  Reader<PoseStampedMsg> reader(participant, "robot_pose");
  MessageArena arena;
  PoseStampedMsg message{};
  message.header = header_message(1'700'000'000'000'000'500, "court", arena);
  message.pose = pose_message({{1.5, 2.25}, 0.0});
  writer.write(message);
  ASSERT_TRUE(reader.wait(std::chrono::seconds(5)));
  const std::vector<std::vector<std::uint8_t>> samples = reader.take_serialized();
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_EQ(samples[0], golden);
}

TEST(CourtMessages, HeadersAndPosesRoundTrip) {
  MessageArena arena;
  for (const std::int64_t ns : {std::int64_t{0}, std::int64_t{1'700'000'000'123'456'789},
                                std::int64_t{-1}, std::int64_t{-1'500'000'000}}) {
    const HeaderMsg header = header_message(ns, "court", arena);
    EXPECT_LT(header.stamp.nanosec, 1'000'000'000u) << ns;
    EXPECT_EQ(stamp_ns(header), ns);
  }
  for (double heading = -3.1; heading < 3.14; heading += 0.37) {
    const Pose2D back = pose_from_message(pose_message({{-2.0, 7.5}, heading}));
    EXPECT_NEAR(back.heading_rad, heading, 1e-12);
    EXPECT_EQ(back.position, Vec2(-2.0, 7.5));
  }
}

NavigationUpdate example_update() {
  NavigationUpdate update;
  update.seq = 7;
  update.capture_time_ns = 1'700'000'000'250'000'000;
  FusedBall ball;
  ball.position_m = {1.0, 2.0};
  ball.covariance_m2 << 4e-4, 1e-4, 1e-4, 9e-4;
  ball.cameras = {0, 2};
  update.world.balls = {ball, FusedBall{{3.0, -1.0}, Eigen::Matrix2d::Zero(), {1}}};
  update.world.robot.emplace().pose = {{0.5, 0.5}, std::numbers::pi / 2};
  update.route.waypoints_m = {{0.5, 0.5}, {0.5, 2.5}, {3.0, 2.5}, {3.0, 2.5}};
  return update;
}

TEST(CourtMessages, AnUpdateBecomesPoseBallsAndRouteInTheCourtFrame) {
  const NavigationUpdate update = example_update();
  MessageArena arena;
  const std::optional<PoseStampedMsg> pose = robot_pose_message(update, arena);
  ASSERT_TRUE(pose);
  EXPECT_STREQ(pose->header.frame_id, "court");
  EXPECT_EQ(stamp_ns(pose->header), update.capture_time_ns);
  EXPECT_NEAR(pose_from_message(pose->pose).heading_rad, std::numbers::pi / 2, 1e-12);

  const PoseArrayMsg balls = balls_message(update, 0.0335, arena);
  ASSERT_EQ(balls.poses._length, 2u);
  EXPECT_EQ(balls.poses._buffer[1].position.x, 3.0);
  EXPECT_EQ(balls.poses._buffer[1].position.z, 0.0335);
  EXPECT_EQ(balls.poses._buffer[1].orientation.w, 1.0);

  const BallArrayMsg estimates = ball_estimates_message(update, 0.0335, arena);
  EXPECT_EQ(estimates.seq, 7u);
  ASSERT_EQ(estimates.balls._length, 2u);
  EXPECT_EQ(estimates.balls._buffer[0].covariance[1], 1e-4);
  EXPECT_EQ(estimates.balls._buffer[0].covariance[3], 9e-4);
  ASSERT_EQ(estimates.balls._buffer[0].cameras._length, 2u);
  EXPECT_EQ(estimates.balls._buffer[0].cameras._buffer[1], 2);

  const PathMsg path = route_message(update, arena);
  ASSERT_EQ(path.poses._length, 4u);
  const auto heading = [&](std::size_t k) {
    return pose_from_message(path.poses._buffer[k].pose).heading_rad;
  };
  EXPECT_NEAR(heading(0), std::numbers::pi / 2, 1e-12);  // each waypoint faces the next
  EXPECT_NEAR(heading(1), 0.0, 1e-12);
  EXPECT_NEAR(heading(3), 0.0, 1e-12);  // a repeated last waypoint keeps the heading
  EXPECT_STREQ(path.poses._buffer[2].header.frame_id, "court");

  NavigationUpdate unseen = update;
  unseen.world.robot.reset();
  EXPECT_FALSE(robot_pose_message(unseen, arena));
}

TEST(CourtMessages, HealthBecomesOneStatusPerCameraAndOneForThePipeline) {
  const nlohmann::json health = {
      {"cameras",
       {{{"name", "north"}, {"state", "running"}, {"frames", 12}},
        {{"name", "south"}, {"state", "retrying"}, {"frames", 3}, {"last_error", "EOF"}}}},
      {"frame_sets", 12},
      {"last_error", ""}};
  MessageArena arena;
  const DiagnosticArrayMsg message = diagnostics_message(health, "court1", 5, arena);
  ASSERT_EQ(message.status._length, 3u);
  const DiagnosticStatusMsg& south = message.status._buffer[1];
  EXPECT_STREQ(south.name, "court1/camera/south");
  EXPECT_EQ(south.level, 1);  // WARN
  ASSERT_EQ(south.values._length, 4u);
  EXPECT_STREQ(south.values._buffer[0].key, "frames");
  EXPECT_STREQ(south.values._buffer[0].value, "3");
  const DiagnosticStatusMsg& pipeline = message.status._buffer[2];
  EXPECT_STREQ(pipeline.name, "court1/pipeline");
  EXPECT_EQ(pipeline.level, 0);
  EXPECT_EQ(pipeline.values._length, 2u);  // the camera list is not a value
}

}  // namespace
}  // namespace ballsight::dds
