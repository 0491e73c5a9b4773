// The robot link over DDS against a court's topics on loopback: every update once and in order,
// reports that reach the hub (and refusals that change nothing), the simulated court's wheels,
// a robot that joins late, and a court that restarts.
#include "ballsight/dds/dds_robot_link.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "ballsight/dds/court_topics.hpp"
#include "ballsight/dds/robot_reports.hpp"
#include "dds_domain.hpp"
#include "sample_update.hpp"
#include "wait_until.hpp"

namespace ballsight::dds {
namespace {

using std::chrono::milliseconds;

NavigationUpdate update(double x) {
  return test::sample_update({Vec2(x, 1.0), 0.25});
}

// A court: its hub, topics and the reports' server on a participant of its own.
struct Court {
  explicit Court(const DomainOptions& domain) : participant(domain) {}
  RobotReports& serve(CourtService::SimulatedDrive drive = {}) {
    reports = std::make_unique<RobotReports>(
        participant,
        RobotReportsContext{hub, {Vec2(-10, -10), Vec2(10, 10)}, [this] { ++replans; }, drive});
    return *reports;
  }

  Participant participant;
  NavigationHub hub;
  CourtTopics topics{participant, hub, [] { return nlohmann::json::object(); }};
  std::unique_ptr<RobotReports> reports;
  int replans = 0;
};

TEST(DdsRobotLink, EveryUpdateOnceInOrderAndReportsReachTheHub) {
  const DomainOptions domain = test::test_domain();
  Court court(domain);
  court.serve();
  const Participant robot(domain);
  DdsRobotLink link(robot);
  court.hub.publish(update(0.5));
  const std::optional<LinkUpdate> first = link.next(milliseconds(10000));
  ASSERT_TRUE(first) << "the first update never came";
  EXPECT_EQ(first->seq, 1u);
  EXPECT_EQ(first->service_id, court.hub.service_id());
  ASSERT_TRUE(first->robot);
  EXPECT_DOUBLE_EQ(first->robot->position.x(), 0.5);
  EXPECT_DOUBLE_EQ(first->robot->heading_rad, 0.25);
  EXPECT_EQ(first->balls_m, std::vector<Vec2>{Vec2(3, 4)});
  EXPECT_EQ(first->visits_m, std::vector<Vec2>{Vec2(3, 4)});
  EXPECT_EQ(first->waypoints_m.size(), 2u);
  const NavigationUpdate published = *court.hub.latest();
  EXPECT_EQ(first->capture_time_ns, published.capture_time_ns);
  EXPECT_EQ(first->published_ns, published.published_ns);
  EXPECT_GE(first->received_ns, first->published_ns);
  for (int k = 0; k < 30; ++k) court.hub.publish(update(k));  // back to back
  EXPECT_EQ(test::take(link, 30, milliseconds(10000)), test::seq_range(2, 31));
  EXPECT_EQ(link.status().transport, "dds");
  EXPECT_TRUE(link.status().connected);
  EXPECT_EQ(link.status().gaps, 0u);
  EXPECT_EQ(link.status().delivered, 31u);

  EXPECT_TRUE(link.acknowledge(31));
  EXPECT_EQ(court.hub.acknowledged(), 31u);
  EXPECT_FALSE(link.acknowledge(99));  // not published yet: refused, nothing changed
  EXPECT_NE(link.status().last_error.find("the court refused"), std::string::npos)
      << link.status().last_error;
  EXPECT_EQ(court.hub.acknowledged(), 31u);

  EXPECT_TRUE(link.report_collected({Vec2(3, 4), Vec2(1, 2)}, 2));
  EXPECT_EQ(court.hub.collected(), (std::vector<Vec2>{Vec2(3, 4), Vec2(1, 2)}));
  ASSERT_TRUE(court.hub.reports().basket);
  EXPECT_EQ(court.hub.reports().basket->value, 2);
  EXPECT_EQ(court.replans, 1);
  // The second is off the court.
  EXPECT_FALSE(link.report_collected({Vec2(1, 1), Vec2(30, 0)}, std::nullopt));
  EXPECT_NE(link.status().last_error.find("report.points[1]"), std::string::npos)
      << link.status().last_error;
  EXPECT_EQ(court.hub.collected().size(), 2u);
  EXPECT_EQ(court.replans, 1);
  EXPECT_TRUE(link.report_unreachable({Vec2(5, 1)}, "stuck"));
  ASSERT_EQ(court.hub.reports().unreachable.size(), 1u);
  EXPECT_EQ(court.hub.reports().unreachable[0].reason, "stuck");
  EXPECT_EQ(court.replans, 2);
  EXPECT_FALSE(link.report_unreachable({Vec2(5, 1)}, ""));  // why is required

  EXPECT_TRUE(link.set_pose({Vec2(-2, 3), 1.5}));
  ASSERT_TRUE(court.hub.robot());
  EXPECT_EQ(court.hub.robot()->value.position, Vec2(-2, 3));
  EXPECT_DOUBLE_EQ(court.hub.robot()->value.heading_rad, 1.5);

  EXPECT_FALSE(link.drive_simulated(31, 0.5, 10.0));  // not a simulated court
  EXPECT_NE(link.status().last_error.find("not a simulated court"), std::string::npos);
  EXPECT_EQ(court.reports->answered(), 8u);
  EXPECT_EQ(court.reports->refused(), 4u);
}

TEST(DdsRobotLink, DrivesTheSimulatedCourtsWheels) {
  const DomainOptions domain = test::test_domain();
  Court court(domain);
  std::uint64_t driven_seq = 0;
  double speed = 0.0, turn_rps = 0.0;
  court.serve([&](std::uint64_t seq, double speed_mps, double turn_rate_rps) {
    driven_seq = seq;
    speed = speed_mps;
    turn_rps = turn_rate_rps;
    return nlohmann::json{{"collected", 2},
                          {"time_s", 1.5},
                          {"odometry", {{"x_m", 1.25}, {"y_m", -0.5}, {"heading_deg", 30.0}}}};
  });
  const Participant robot(domain);
  DdsRobotLink link(robot);
  const std::optional<nlohmann::json> answer = link.drive_simulated(7, 0.8, 90.0);
  ASSERT_TRUE(answer) << link.status().last_error;
  EXPECT_EQ((*answer)["collected"], 2);
  EXPECT_EQ((*answer)["time_s"], 1.5);
  const nlohmann::json& odometry = (*answer)["odometry"];  // the wheels' odometry, carried
  EXPECT_EQ(odometry["x_m"], 1.25);
  EXPECT_EQ(odometry["y_m"], -0.5);
  EXPECT_NEAR(odometry["heading_deg"].get<double>(), 30.0, 1e-12);
  EXPECT_EQ(driven_seq, 7u);
  EXPECT_DOUBLE_EQ(speed, 0.8);
  EXPECT_NEAR(turn_rps, 3.14159265358979 / 2, 1e-12);
}

// A robot that joins after the court published gets its latest update at once; when the court
// restarts (a new hub: a new service id, seq from 1 again) the link follows it.
TEST(DdsRobotLink, ALateRobotGetsTheLatestAndARestartedCourtIsFollowed) {
  const DomainOptions domain = test::test_domain();
  auto court = std::make_unique<Court>(domain);
  for (int k = 0; k < 5; ++k) court->hub.publish(update(k));
  ASSERT_TRUE(test::wait_until([&] { return court->topics.written() >= 5; }));
  const Participant robot(domain);
  DdsRobotLink link(robot);
  const std::optional<LinkUpdate> latest = link.next(milliseconds(10000));
  ASSERT_TRUE(latest) << "the latest update never came";
  EXPECT_EQ(latest->seq, 5u);
  const std::string first_service = latest->service_id;

  court.reset();
  ASSERT_TRUE(test::wait_until([&] { return !link.status().connected; }, milliseconds(20000)))
      << "the link never saw the court go";
  court = std::make_unique<Court>(domain);
  court->serve();
  ASSERT_TRUE(test::wait_until([&] { return link.status().connected; }, milliseconds(20000)))
      << "the link never found the court again";
  court->hub.publish(update(1.0));
  const std::optional<LinkUpdate> restarted = link.next(milliseconds(10000));
  ASSERT_TRUE(restarted) << "no update from the restarted court";
  EXPECT_EQ(restarted->seq, 1u);
  EXPECT_NE(restarted->service_id, first_service);
  EXPECT_EQ(link.status().reconnects, 1);
  EXPECT_TRUE(link.acknowledge(1));
  EXPECT_EQ(court->hub.acknowledged(), 1u);
}

}  // namespace
}  // namespace ballsight::dds
