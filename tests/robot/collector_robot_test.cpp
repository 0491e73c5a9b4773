// The collector's controller against a scripted link (robot/collector_robot.hpp): a robot that
// cannot move however it is driven stalls on the way to its ball, recovers, and after
// give_up_after stalls marks the ball unreachable, with why; the ball is still seen (the world
// model keeps it), the route leaves it out, and the robot, with no other ball left, is done.
#include "ballsight/robot/collector_robot.hpp"

#include <gtest/gtest.h>

#include <atomic>

namespace ballsight {
namespace {

// A court where the robot stands at (2, 1) whatever it is told, a ball 3 m ahead; the simulated
// clock moves 0.1 s a command. It stops the robot once kStopAfter updates were read.
class StuckRobotLink : public RobotLink {
 public:
  explicit StuckRobotLink(std::atomic<bool>& stop) : stop_(stop) {}

  std::optional<LinkUpdate> next(std::chrono::milliseconds) override {
    if (++seq_ >= kStopAfter) stop_ = true;
    LinkUpdate u;
    u.seq = seq_;
    u.capture_time_ns = static_cast<std::int64_t>(seq_) * 100'000'000;
    u.received_ns = u.capture_time_ns;
    u.robot = Pose2D{Vec2(2, 1), 0.0};
    u.balls_m = {Vec2(5.02, 1)};  // seen a little off where the route goes
    if (!given_up_) {
      u.visits_m = {Vec2(5, 1)};
      u.waypoints_m = {Vec2(2.3, 1), Vec2(5, 1)};
    }
    return u;
  }
  std::optional<LinkUpdate> latest(std::chrono::milliseconds timeout) override {
    return next(timeout);
  }
  bool acknowledge(std::uint64_t) override { return true; }
  bool report_collected(const std::vector<Vec2>&, std::optional<int>) override { return true; }
  bool report_unreachable(const std::vector<Vec2>& positions, const std::string& why) override {
    given_up_ = true;
    marked = positions;
    reason = why;
    at_seq = seq_;
    return true;
  }
  bool set_pose(const Pose2D&) override { return true; }
  std::optional<nlohmann::json> drive_simulated(std::uint64_t, double, double) override {
    time_s_ += 0.1;
    return nlohmann::json{{"collected", 0}, {"time_s", time_s_}};
  }
  LinkStatus status() const override { return {}; }
  void stop() override {}

  std::vector<Vec2> marked;
  std::string reason;
  std::uint64_t at_seq = 0;

 private:
  static constexpr std::uint64_t kStopAfter = 1000;  // 100 s of the court's clock
  std::atomic<bool>& stop_;
  std::uint64_t seq_ = 0;
  double time_s_ = 0.0;
  bool given_up_ = false;
};

TEST(CollectorRobot, MarksABallItCannotReachUnreachableAndGoesOn) {
  std::atomic<bool> stop{false};
  StuckRobotLink link(stop);
  CollectorOptions options;
  const CollectorResult result = run_collector(link, options, stop);
  EXPECT_TRUE(result.done);  // no ball left but the one it gave up on
  EXPECT_EQ(result.unreachable, 1);
  EXPECT_EQ(result.stalls, 3);  // none after it: no ball left to stall on
  ASSERT_EQ(link.marked.size(), 1u);
  EXPECT_EQ(link.marked[0], Vec2(5.02, 1));
  EXPECT_EQ(link.reason, "no progress on the way to it after 3 recoveries");
  // Three windows of 10 s, each followed by its recovery (2 s back, 2 s ahead): 30-45 s.
  EXPECT_GT(link.at_seq, 300u);
  EXPECT_LT(link.at_seq, 450u);
}

}  // namespace
}  // namespace ballsight
