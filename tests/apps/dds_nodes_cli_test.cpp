// The court on DDS as separate processes: four `camera-node --sim` and a `court-node --sim
// --camera-nodes`, on loopback, against the single-process pipeline on the same frames.

#include <gtest/gtest.h>

#include <map>

#include "ballsight/core/child_process.hpp"
#include "ballsight/dds/court_messages.hpp"
#include "ballsight/dds/detection_messages.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/net/bearer_token.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/service/court_service.hpp"
#include "ballsight/service/simulated_court.hpp"
#include "dds_domain.hpp"
#include "http_request.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using namespace std::chrono_literals;

constexpr int kRateHz = 5;  // ten rendering processes share the machine's two cores

std::vector<std::string> node_args(std::string command, const dds::DomainOptions& domain,
                                   std::uint64_t seed, std::vector<std::string> more) {
  std::vector<std::string> args{std::move(command),
                                "--sim",
                                "--seed",
                                std::to_string(seed),
                                "--balls",
                                "12",
                                "--rate",
                                std::to_string(kRateHz),
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

ReceivedSet received_set(const dds::BallArrayMsg& m) {
  ReceivedSet set{dds::stamp_ns(m.header), {}, {}};
  for (std::uint32_t k = 0; k < m.balls._length; ++k) {
    const dds::BallMsg& b = m.balls._buffer[k];
    set.balls.emplace_back(b.position.x, b.position.y);
    set.cameras.insert(b.cameras._buffer, b.cameras._buffer + b.cameras._length);
  }
  return set;
}

// One simulated court as separate processes: a `court-node --sim --camera-nodes` and four
// `camera-node --sim`, under a namespace of its own; and readers of its world model and route.
struct DistributedCourt {
  DistributedCourt(const dds::Participant& participant, const dds::DomainOptions& court_domain,
                   std::uint64_t court_seed, const std::filesystem::path& dir)
      : domain(court_domain),
        seed(court_seed),
        log_dir(dir),
        // Deep enough that the last set's route is still kept when the test replays every set
        // in one process, which on a loaded machine takes minutes while the court publishes on.
        estimates(std::make_unique<dds::Reader<dds::BallArrayMsg>>(
            participant, domain.ns + "/ball_estimates", dds::TopicQos{true, 2000})),
        route(std::make_unique<dds::Reader<dds::PathMsg>>(participant, domain.ns + "/route",
                                                          dds::TopicQos{true, 2000})),
        court(BALLSIGHT_CLI, node_args("court-node", domain, seed, {"--camera-nodes"}),
              dir / ("court" + std::to_string(seed) + ".log")) {
    for (int k = 0; k < 4; ++k) cameras.push_back(start_camera(k));
  }
  std::unique_ptr<ChildProcess> start_camera(int k) const {
    return std::make_unique<ChildProcess>(
        BALLSIGHT_CLI, node_args("camera-node", domain, seed, {"--camera", std::to_string(k)}),
        log_dir / ("court" + std::to_string(seed) + "-camera" + std::to_string(k) + "-" +
                   random_hex(4) + ".log"));
  }
  // Takes what arrived; true once five sets came and the last fused all four cameras.
  bool take() {
    estimates->take([&](const dds::BallArrayMsg& m) { received.push_back(received_set(m)); });
    return received.size() >= 5 && received.back().cameras.size() == 4;
  }
  // Waits until a set fuses the cameras `want`, up to `timeout`; the cameras of the last set.
  std::set<int> wait_for_fused(const std::set<int>& want, std::chrono::seconds timeout) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    std::set<int> fused;
    while (fused != want && std::chrono::steady_clock::now() < until)
      if (estimates->wait(100ms))
        estimates->take([&](const dds::BallArrayMsg& m) { fused = received_set(m).cameras; });
    return fused;
  }

  dds::DomainOptions domain;
  std::uint64_t seed;
  std::filesystem::path log_dir;
  std::unique_ptr<dds::Reader<dds::BallArrayMsg>> estimates;
  std::unique_ptr<dds::Reader<dds::PathMsg>> route;
  ChildProcess court;
  std::vector<std::unique_ptr<ChildProcess>> cameras;
  std::vector<ReceivedSet> received;
};

// The same frames through one process's publisher (pipeline, planner, hub): every set the court
// node published, in order, of the cameras it fused; its last world model and route.
void expect_one_process_makes_the_same(DistributedCourt& court) {
  SCOPED_TRACE(court.domain.ns);
  const ReceivedSet& last = court.received.back();
  const SimulatedCourt simulated({court.seed, 12, 0.25, {}, {}, {}});
  const BallsightPipelineOptions options = service_pipeline_options(simulated.site());
  const auto detector = make_ballsight_pipeline(simulated.cameras(), options);
  UpdatePublisher publisher(simulated.site(), {CourtMethod::ballsight, simulated.cameras(), {}},
                            PlannerOptions{});
  NavigationHub hub;
  const std::int64_t period_ns = 1'000'000'000 / kRateHz;
  for (const ReceivedSet& set : court.received) {
    ASSERT_EQ(set.capture_ns % period_ns, 0) << "camera nodes stamp whole ticks";
    const auto tick = static_cast<std::uint64_t>(set.capture_ns / period_ns);
    // The cameras the court node fused in this set (a camera late under load is left out, and
    // the pipeline remembers hidden balls from set to set; each camera sees some of 12 balls).
    CameraDetectionLists lists(4);
    for (const int k : set.cameras)
      lists[static_cast<std::size_t>(k)] =
          detector->detect(static_cast<std::size_t>(k),
                           simulated.render(static_cast<std::size_t>(k), simulated.scene(), tick));
    publisher.publish_detections(lists, set.capture_ns, hub);
  }
  const NavigationUpdate one = *hub.latest();
  ASSERT_EQ(one.world.balls.size(), last.balls.size());
  for (std::size_t k = 0; k < last.balls.size(); ++k)
    EXPECT_LT((one.world.balls[k].position_m - last.balls[k]).norm(), 1e-9) << "ball " << k;
  EXPECT_GE(one.world.balls.size(), 10u);  // the court's 12 balls, a cluster may count fewer

  std::vector<Vec2> route;  // the court node's route of the last set
  const auto until = std::chrono::steady_clock::now() + 10s;
  while (route.empty() && std::chrono::steady_clock::now() < until) {
    court.route->wait(100ms);
    court.route->take([&](const dds::PathMsg& m) {
      if (dds::stamp_ns(m.header) != last.capture_ns) return;
      for (std::uint32_t k = 0; k < m.poses._length; ++k)
        route.emplace_back(m.poses._buffer[k].pose.position.x, m.poses._buffer[k].pose.position.y);
    });
  }
  ASSERT_EQ(route.size(), one.route.waypoints_m.size());
  ASSERT_GT(route.size(), 1u);
  for (std::size_t k = 0; k < route.size(); ++k)
    EXPECT_LT((one.route.waypoints_m[k] - route[k]).norm(), 1e-9) << "waypoint " << k;
}

// Two courts on one DDS domain, each a court node and four camera nodes under its namespace:
// every court's world model and route equal what one process makes of the same frames (the frames
// of a simulated tick are the same wherever they are rendered, the detections cross DDS whole), and
// a camera node killed leaves its court with three cameras until it is back.
TEST(DdsNodes, TwoCourtsOfFourCameraNodesMakeWhatOneProcessMakes) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  dds::DomainOptions root = domain;  // the courts' namespaces are below the test's own
  root.ns.clear();
  const dds::Participant participant(root);
  std::vector<std::unique_ptr<DistributedCourt>> courts;
  for (const std::uint64_t seed : {3, 5}) {
    dds::DomainOptions court_domain = domain;
    court_domain.ns = domain.ns + "/court" + std::to_string(seed);
    courts.push_back(
        std::make_unique<DistributedCourt>(participant, court_domain, seed, dir.path()));
  }
  const auto until = std::chrono::steady_clock::now() + 90s;
  bool done = false;
  while (!done && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(100ms);
    done = courts[0]->take() & courts[1]->take();
  }
  for (const auto& court : courts) {
    ASSERT_GE(court->received.size(), 5u) << court->court.log_text();
    ASSERT_EQ(court->received.back().cameras.size(), 4u) << court->court.log_text();
    expect_one_process_makes_the_same(*court);
  }
  EXPECT_NE(courts[0]->received.back().balls, courts[1]->received.back().balls)
      << "two courts, two scenes";

  // A camera node of the first court killed: that court carries on with three cameras (the other
  // court with four), then takes it back.
  courts[0]->cameras[2]->stop();
  const std::set<int> all{0, 1, 2, 3};
  EXPECT_EQ(courts[0]->wait_for_fused({0, 1, 3}, 30s), (std::set<int>{0, 1, 3}));
  EXPECT_EQ(courts[1]->wait_for_fused(all, 5s), all);
  courts[0]->cameras[2] = courts[0]->start_camera(2);
  EXPECT_EQ(courts[0]->wait_for_fused(all, 30s), all) << courts[0]->court.log_text();
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
  const std::string camera = SimulatedCourt({3, 12, 0.25, {}, {}, {}}).site().cameras[3].name;
  dds::Reader<dds::CameraDetectionsMsg> detections(participant, dds::detections_topic(camera));
  ChildProcess court(BALLSIGHT_CLI, node_args("court-node", domain, 3, {}), dir / "court.log");
  std::map<std::string, int> got;
  const auto until = std::chrono::steady_clock::now() + 60s;
  while (std::chrono::steady_clock::now() < until && got.size() < 5) {
    std::this_thread::sleep_for(50ms);
    pose.take([&](const dds::PoseStampedMsg& m) {
      if (std::string(m.header.frame_id) == "court") ++got["robot_pose"];
    });
    route.take([&](const dds::PathMsg& m) { got["route"] += m.poses._length > 1 ? 1 : 0; });
    balls.take([&](const dds::PoseArrayMsg& m) { got["balls"] += m.poses._length >= 10; });
    diagnostics.take([&](const dds::DiagnosticArrayMsg& m) {
      got["diagnostics"] += m.status._length == 5 ? 1 : 0;  // four cameras and the pipeline
    });
    detections.take([&](const dds::CameraDetectionsMsg& m) {
      got["detections"] += std::string(m.header.frame_id) == camera && m.detections._length > 0;
    });
    for (auto it = got.begin(); it != got.end();) it = it->second == 0 ? got.erase(it) : ++it;
  }
  EXPECT_EQ(got.size(), 5u) << court.log_text();
}

// `court-node --record`: the run in an MCAP file, every update with its frames, which `record
// info` reads through and finds consistent with its summary.
TEST(DdsNodes, ACourtNodeRecordsItsRun) {
  const test::TempDir dir;
  const std::string path = (dir / "run.mcap").string();
  const test::CliResult run = test::run_cli(
      node_args("court-node", test::test_domain(), 3, {"--duration", "3", "--record", path}));
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  EXPECT_NE(run.stdout_text.find("ballsight court-node: recorded "), std::string::npos)
      << run.stdout_text;
  const test::CliResult info = test::run_cli({"record", "info", path, "--json"});
  ASSERT_EQ(info.exit_code, 0) << info.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(info.stdout_text);
  EXPECT_EQ(j["summary"], "agrees");
  std::map<std::string, int> messages;
  for (const auto& channel : j["channels"]) messages[channel["topic"]] = channel["messages"];
  EXPECT_GE(messages["/navigation"], 5);
  EXPECT_EQ(messages["/balls"], messages["/navigation"]);
  int cameras = 0;
  for (const auto& [topic, count] : messages) {
    if (!topic.ends_with("/image")) continue;
    ++cameras;
    EXPECT_EQ(count, messages["/navigation"]) << topic;
  }
  EXPECT_EQ(cameras, 4);
}

// `court-node --serve`: the navigation service's HTTP API inside the court node serves the very
// updates its DDS topics carry.
TEST(DdsNodes, ACourtNodeServesTheNavigationServiceAsWell) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  const dds::Participant participant(domain);
  dds::Reader<dds::PathMsg> route(participant, "route");
  ChildProcess court(BALLSIGHT_CLI,
                     node_args("court-node", domain, 3,
                               {"--serve", "--listen", "127.0.0.1:0", "--token-file",
                                (dir / "token").string(), "--web", ""}),
                     dir / "court.log");
  const std::optional<std::string> line = court.wait_for_line("/api/v1/", 60s);
  ASSERT_TRUE(line) << court.log_text();
  const auto port = static_cast<unsigned short>(
      std::stoi(line->substr(line->find("127.0.0.1:") + std::string("127.0.0.1:").size())));
  const std::string token = read_or_create_token(dir / "token");
  std::map<std::int64_t, std::vector<Vec2>> topic_routes;  // by capture time
  bool compared = false;
  const auto until = std::chrono::steady_clock::now() + 30s;
  while (!compared && std::chrono::steady_clock::now() < until) {
    const test::Reply reply =
        test::request(port, boost::beast::http::verb::get, "/api/v1/route", "", token);
    if (reply.status != 200) {  // no update yet
      std::this_thread::sleep_for(100ms);
      continue;
    }
    route.wait(500ms);
    route.take([&](const dds::PathMsg& m) {
      std::vector<Vec2>& points = topic_routes[dds::stamp_ns(m.header)];
      for (std::uint32_t k = 0; k < m.poses._length; ++k)
        points.emplace_back(m.poses._buffer[k].pose.position.x, m.poses._buffer[k].pose.position.y);
    });
    const auto it = topic_routes.find(reply.body["capture_time_ns"].get<std::int64_t>());
    if (it == topic_routes.end()) continue;
    const nlohmann::json& waypoints = reply.body["waypoints_m"];
    ASSERT_EQ(waypoints.size(), it->second.size());
    ASSERT_GT(waypoints.size(), 1u);
    for (std::size_t k = 0; k < waypoints.size(); ++k)
      EXPECT_EQ(Vec2(waypoints[k][0], waypoints[k][1]), it->second[k]) << "waypoint " << k;
    compared = true;
  }
  EXPECT_TRUE(compared) << "no update seen both over HTTP and on DDS\n" << court.log_text();
}

// The robot on DDS: `robot --dds` drives `court-node --sim` through the court's navigation and
// robot/* topics alone (no HTTP), and collects every ball without missing an update.
TEST(DdsNodes, ARobotOnDdsCollectsEveryBallOfTheSimulatedCourt) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  ChildProcess court(BALLSIGHT_CLI, node_args("court-node", domain, 3, {"--duration", "200"}),
                     dir / "court.log");
  const test::CliResult robot =
      test::run_cli({"robot", "--dds", "--loopback", "--domain", std::to_string(*domain.domain),
                     "--namespace", domain.ns, "--max-time", "150"});
  EXPECT_EQ(robot.exit_code, 0) << robot.stderr_text;
  EXPECT_NE(robot.stdout_text.find("no ball left"), std::string::npos)
      << robot.stdout_text << court.log_text();
  EXPECT_NE(robot.stdout_text.find("12 collected; 0 stalls; 0 updates missed"), std::string::npos)
      << robot.stdout_text;
}

// ROS 2's default middleware family reads ballsight's topics: a Fast DDS 2.9.1 reader (types
// from fastddsgen -typeros2, XCDR1 only, ROS 2's default QoS) receives the pose, the balls and the
// route with ROS 2's type names and the court frame.
TEST(DdsNodes, AFastDdsReaderReceivesPoseBallsAndRoute) {
  const test::TempDir dir;
  const dds::DomainOptions domain = test::test_domain();
  ChildProcess court(BALLSIGHT_CLI, node_args("court-node", domain, 3, {}), dir / "court.log");
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

// `eval nodes` measures both configurations: every frame set's world model reaches its reader,
// the camera nodes' detections come before it, and the topics carry what a court writes.
TEST(EvalNodes, MeasuresOneProcessAndCameraNodesOnLoopback) {
  const dds::DomainOptions domain = test::test_domain();
  const test::CliResult run =
      test::run_cli({"eval", "nodes", "--seconds", "3", "--warmup", "0.5", "--balls", "12",
                     "--rate", "5", "--domain", std::to_string(*domain.domain), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const nlohmann::json out = nlohmann::json::parse(run.stdout_text);
  for (const std::string config : {"one_process", "camera_nodes"}) {
    SCOPED_TRACE(config);
    const nlohmann::json& latency = out[config]["latency_ms"];
    EXPECT_GE(latency["count"].get<int>(), 10) << "5 Hz for 3 s";
    EXPECT_LE(latency["p50"].get<double>(), latency["p99"].get<double>());
    EXPECT_NEAR(out[config]["topics"]["route"]["messages_per_s"].get<double>(), 5.0, 2.0);
    EXPECT_GT(
        out[config]["topics"]["cameras/camera_0/detections"]["bytes_per_message"].get<double>(),
        100.0);
  }
  const nlohmann::json& nodes = out["camera_nodes"];
  EXPECT_EQ(nodes["cpu_pct"].size(), 5u) << "four camera nodes and a court node";
  EXPECT_LT(nodes["camera_ms"]["p50"].get<double>(), nodes["latency_ms"]["p50"].get<double>());
  EXPECT_FALSE(out["one_process"].contains("camera_ms"));
}

TEST(EvalNodes, RefusesABadDuration) {
  const test::CliResult run = test::run_cli({"eval", "nodes", "--seconds", "0"});
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.stderr_text.find("--seconds"), std::string::npos) << run.stderr_text;
}

}  // namespace
}  // namespace ballsight
