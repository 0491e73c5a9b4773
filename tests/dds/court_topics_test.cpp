#include "ballsight/dds/court_topics.hpp"

#include <gtest/gtest.h>

#include "ballsight/dds/court_messages.hpp"
#include "dds_domain.hpp"
#include "wait_until.hpp"

namespace ballsight::dds {
namespace {

using namespace std::chrono_literals;

NavigationUpdate update_with_balls(int balls) {
  NavigationUpdate update;
  update.capture_time_ns = utc_now_ns();
  for (int k = 0; k < balls; ++k)
    update.world.balls.push_back({{1.0 + k, 2.0}, Eigen::Matrix2d::Identity() * 1e-4, {k % 4}});
  update.world.robot.emplace().pose = {{0.5, 0.5}, 0.0};
  update.route.waypoints_m = {{0.5, 0.5}, {1.0, 2.0}, {2.0, 2.0}};
  return update;
}

template <class Msg, class Visit>
bool receive(Reader<Msg>& reader, Visit&& visit) {
  const auto until = std::chrono::steady_clock::now() + 10s;
  while (std::chrono::steady_clock::now() < until) {
    if (reader.wait(200ms) && reader.take(visit) > 0) return true;
  }
  return false;
}

// The hub's updates reach ROS 2-style subscribers on every topic; one that joins after an update
// still gets the latest balls and route (transient-local), and the health comes once a second.
TEST(CourtTopics, EveryUpdateReachesSubscribersAndLateJoinersGetTheLatestRoute) {
  const Participant participant(test::test_domain());
  NavigationHub hub;
  Reader<PoseStampedMsg> robot_pose(participant, "robot_pose");
  Reader<DiagnosticArrayMsg> diagnostics(participant, "diagnostics");
  CourtTopicsOptions options;
  options.health_period = 100ms;
  const CourtTopics topics(
      participant, hub,
      [] {
        return nlohmann::json{{"cameras", {{{"name", "north"}, {"state", "running"}}}}};
      },
      options);
  hub.publish(update_with_balls(3));
  Pose2D pose;
  ASSERT_TRUE(
      receive(robot_pose, [&](const PoseStampedMsg& m) { pose = pose_from_message(m.pose); }));
  EXPECT_EQ(pose.position, Vec2(0.5, 0.5));

  const std::uint64_t seq = hub.publish(update_with_balls(5));
  ASSERT_TRUE(test::wait_until([&] { return topics.written() >= 2; }))
      << "the second update was never written";
  // Late joiners (with the transient-local QoS of the latest values).
  Reader<BallArrayMsg> estimates(participant, "ball_estimates", {true, 1});
  Reader<PathMsg> route(participant, "route", {true, 1});
  Reader<PoseArrayMsg> balls(participant, "balls", {true, 1});
  std::uint64_t got_seq = 0;
  std::size_t got_balls = 0, got_poses = 0, got_waypoints = 0;
  ASSERT_TRUE(receive(estimates, [&](const BallArrayMsg& m) {
    got_seq = m.seq;
    got_balls = m.balls._length;
  }));
  ASSERT_TRUE(receive(balls, [&](const PoseArrayMsg& m) { got_poses = m.poses._length; }));
  ASSERT_TRUE(receive(route, [&](const PathMsg& m) { got_waypoints = m.poses._length; }));
  EXPECT_EQ(got_seq, seq);
  EXPECT_EQ(got_balls, 5u);
  EXPECT_EQ(got_poses, 5u);
  EXPECT_EQ(got_waypoints, 3u);
  std::string camera;
  ASSERT_TRUE(receive(diagnostics,
                      [&](const DiagnosticArrayMsg& m) { camera = m.status._buffer[0].name; }));
  EXPECT_EQ(camera, "ballsight/camera/north");
}

}  // namespace
}  // namespace ballsight::dds
