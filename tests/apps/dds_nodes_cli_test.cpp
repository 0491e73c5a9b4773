// The court on DDS as separate processes: four `camera-node --sim` and a `court-node --sim
// --camera-nodes`, on loopback, against the single-process pipeline on the same frames.

#include <gtest/gtest.h>

#include <map>

#include "ballsight/core/child_process.hpp"
#include "ballsight/dds/court_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/eval/simulated_court.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "dds_domain.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using namespace std::chrono_literals;

std::vector<std::string> node_args(std::string command, const dds::DomainOptions& domain,
                                   std::vector<std::string> more) {
  std::vector<std::string> args{std::move(command),
                                "--sim",
                                "--seed",
                                "3",
                                "--balls",
                                "12",
                                "--loopback",
                                "--domain",
                                std::to_string(*domain.domain),
                                "--namespace",
                                domain.ns};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

struct ReceivedSet {
  std::int64_t capture_ns = 0;
  std::vector<Vec2> balls;
  std::set<int> cameras;
};

// Every court's world model equals what one process makes of the same frames: the frames of a
// simulated tick are the same wherever they are rendered, the detections cross DDS whole.
TEST(DdsNodes, FourCameraNodesAndACourtNodeFuseWhatOneProcessFuses) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  const dds::Participant participant(domain);
  dds::Reader<dds::BallArrayMsg> estimates(participant, "ball_estimates", {true, 1});
  ChildProcess court(BALLSIGHT_CLI, node_args("court-node", domain, {"--camera-nodes"}),
                     dir / "court.log");
  std::vector<std::unique_ptr<ChildProcess>> cameras;
  for (int k = 0; k < 4; ++k) {
    cameras.push_back(std::make_unique<ChildProcess>(
        BALLSIGHT_CLI, node_args("camera-node", domain, {"--camera", std::to_string(k)}),
        dir / ("camera" + std::to_string(k) + ".log")));
  }
  std::vector<ReceivedSet> received;
  const auto until = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < until) {
    if (!estimates.wait(200ms)) continue;
    estimates.take([&](const dds::BallArrayMsg& m) {
      ReceivedSet set{dds::stamp_ns(m.header), {}, {}};
      for (std::uint32_t k = 0; k < m.balls._length; ++k) {
        const dds::BallMsg& b = m.balls._buffer[k];
        set.balls.emplace_back(b.position.x, b.position.y);
        set.cameras.insert(b.cameras._buffer, b.cameras._buffer + b.cameras._length);
      }
      received.push_back(set);
    });
    if (received.size() >= 5 && received.back().cameras.size() == 4) break;
  }
  ASSERT_GE(received.size(), 5u) << court.log_text();
  const ReceivedSet& last = received.back();
  ASSERT_EQ(last.cameras.size(), 4u) << "the last set did not fuse all four cameras";

  // The same frames through one process's pipeline (its sequence: every set received).
  const SimulatedCourt simulated({3, 12, 0.25});
  const auto pipeline =
      make_ballsight_pipeline(simulated.cameras(), service_pipeline_options(simulated.site()));
  const std::int64_t period_ns = 100'000'000;  // --rate 10
  WorldModel world;
  for (const ReceivedSet& set : received) {
    ASSERT_EQ(set.capture_ns % period_ns, 0) << "camera nodes stamp whole ticks";
    const auto tick = static_cast<std::uint64_t>(set.capture_ns / period_ns);
    std::vector<cv::Mat> frames;
    for (std::size_t k = 0; k < 4; ++k)
      frames.push_back(simulated.render(k, simulated.scene(), tick));
    world = pipeline->process(frames).world;
  }
  ASSERT_EQ(world.balls.size(), last.balls.size());
  for (std::size_t k = 0; k < last.balls.size(); ++k)
    EXPECT_LT((world.balls[k].position_m - last.balls[k]).norm(), 1e-9) << "ball " << k;
  EXPECT_GE(world.balls.size(), 10u);  // the court's 12 balls, a cluster may count fewer

  // A camera node killed: its court carries on with three cameras, then takes it back.
  cameras[2]->stop();
  const auto fused_cameras_soon = [&](std::size_t want) {
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    std::size_t seen = 0;
    while (std::chrono::steady_clock::now() < deadline && seen != want) {
      if (!estimates.wait(200ms)) continue;
      estimates.take([&](const dds::BallArrayMsg& m) {
        std::set<int> c;
        for (std::uint32_t k = 0; k < m.balls._length; ++k)
          c.insert(m.balls._buffer[k].cameras._buffer,
                   m.balls._buffer[k].cameras._buffer + m.balls._buffer[k].cameras._length);
        seen = c.size();
      });
    }
    return seen;
  };
  EXPECT_EQ(fused_cameras_soon(3), 3u);
  cameras[2] = std::make_unique<ChildProcess>(
      BALLSIGHT_CLI, node_args("camera-node", domain, {"--camera", "2"}), dir / "camera2b.log");
  EXPECT_EQ(fused_cameras_soon(4), 4u);
}

// `court-node --sim` alone renders its cameras itself and writes every topic.
TEST(DdsNodes, ACourtNodeAloneOnTheSimulatedCourtWritesEveryTopic) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  const dds::Participant participant(domain);
  dds::Reader<dds::PoseStampedMsg> pose(participant, "robot_pose");
  dds::Reader<dds::PathMsg> route(participant, "route", {true, 1});
  dds::Reader<dds::PoseArrayMsg> balls(participant, "balls", {true, 1});
  dds::Reader<dds::DiagnosticArrayMsg> diagnostics(participant, "diagnostics");
  ChildProcess court(BALLSIGHT_CLI, node_args("court-node", domain, {}), dir / "court.log");
  std::map<std::string, int> got;
  const auto until = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < until && got.size() < 4) {
    std::this_thread::sleep_for(50ms);
    pose.take([&](const dds::PoseStampedMsg& m) {
      if (std::string(m.header.frame_id) == "court") ++got["robot_pose"];
    });
    route.take([&](const dds::PathMsg& m) { got["route"] += m.poses._length > 1 ? 1 : 0; });
    balls.take([&](const dds::PoseArrayMsg& m) { got["balls"] += m.poses._length >= 10; });
    diagnostics.take([&](const dds::DiagnosticArrayMsg& m) {
      got["diagnostics"] += m.status._length == 5 ? 1 : 0;  // four cameras and the pipeline
    });
    for (auto it = got.begin(); it != got.end();) it = it->second == 0 ? got.erase(it) : ++it;
  }
  EXPECT_EQ(got.size(), 4u) << court.log_text();
}

// ROS 2's default middleware family reads ballsight's topics: a Fast DDS 2.9.1 reader (types
// from fastddsgen -typeros2, XCDR1 only, ROS 2's default QoS) receives the pose, the balls and the
// route with ROS 2's type names and the court frame.
TEST(DdsNodes, AFastDdsReaderReceivesPoseBallsAndRoute) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  ChildProcess court(BALLSIGHT_CLI, node_args("court-node", domain, {}), dir / "court.log");
  ASSERT_TRUE(court.wait_for_line("court-node:", 60s)) << court.log_text();
  ChildProcess listener(std::filesystem::path(BALLSIGHT_CLI).parent_path() / "fastdds_listener",
                        {"--namespace", domain.ns, "--domain", std::to_string(*domain.domain),
                         "--count", "3", "--timeout-s", "60"},
                        dir / "listener.log");
  ASSERT_EQ(listener.wait(90s), 0) << listener.log_text();
  const std::string log = listener.log_text();
  for (const std::string type :
       {"geometry_msgs::msg::dds_::PoseStamped_", "geometry_msgs::msg::dds_::PoseArray_",
        "nav_msgs::msg::dds_::Path_"}) {
    EXPECT_NE(log.find("\"type\":\"" + type + "\""), std::string::npos) << type << "\n" << log;
  }
  EXPECT_NE(log.find("\"frame_id\":\"court\""), std::string::npos) << log;
  EXPECT_NE(log.find("0.0335"), std::string::npos) << "balls at their centre height\n" << log;
}

}  // namespace
}  // namespace ballsight
