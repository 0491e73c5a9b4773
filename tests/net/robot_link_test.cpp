// The robot's client against the real server on 127.0.0.1: every update once and in order, over
// the stream or by long-polling; writes reach the service; the link survives the service going
// away and coming back, on the same run (resumed) or a new one (followed from its start).
#include <gtest/gtest.h>

#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/net/api.hpp"
#include "ballsight/net/http_robot_link.hpp"
#include "ballsight/net/http_server.hpp"
#include "sample_update.hpp"

namespace ballsight {
namespace {

constexpr const char* kLinkToken = "0123456789abcdef0123";
using std::chrono::milliseconds;

HttpServerOptions server_options(unsigned short port = 0) {
  HttpServerOptions o;
  o.port = port;
  o.token = kLinkToken;
  return o;
}

RobotLinkOptions link_options(unsigned short port, bool websocket) {
  RobotLinkOptions o;
  o.port = port;
  o.token = kLinkToken;
  o.websocket = websocket;
  o.poll_wait = milliseconds(500);
  o.backoff = {milliseconds(20), milliseconds(200), 2.0};
  return o;
}

NavigationUpdate update(double x) {
  return test::sample_update({Vec2(x, 1.0), 0.25});
}

class RobotLinkTransports : public testing::TestWithParam<bool> {};

TEST_P(RobotLinkTransports, EveryUpdateOnceInOrderAndWritesReachTheService) {
  NavigationHub hub;
  ApiContext context{hub, {"ne"}, SiteCourt{}, 0.0335};
  HttpServer server(server_options(), api_v1_routes(context));
  hub.publish(update(0.5));
  HttpRobotLink link(link_options(server.port(), GetParam()));
  const std::optional<LinkUpdate> first = link.next(milliseconds(5000));
  ASSERT_TRUE(first);
  EXPECT_EQ(first->seq, 1u);
  EXPECT_EQ(first->service_id, hub.service_id());
  ASSERT_TRUE(first->robot);
  EXPECT_DOUBLE_EQ(first->robot->position.x(), 0.5);
  EXPECT_NEAR(first->robot->heading_rad, 0.25, 1e-12);
  EXPECT_EQ(first->waypoints_m.size(), 2u);
  EXPECT_GE(first->received_ns, first->published_ns);
  for (int k = 0; k < 30; ++k) {
    hub.publish(update(k));
    std::this_thread::sleep_for(milliseconds(2));
  }
  EXPECT_EQ(test::take(link, 30), test::seq_range(2, 31));
  EXPECT_EQ(link.status().transport, GetParam() ? "websocket" : "long-poll");
  EXPECT_EQ(link.status().gaps, 0u);
  EXPECT_TRUE(link.acknowledge(31));
  EXPECT_EQ(hub.acknowledged(), 31u);
  EXPECT_TRUE(link.report_collected({Vec2(3, 4)}, std::nullopt)) << link.status().last_error;
  EXPECT_EQ(hub.collected(), std::vector<Vec2>{Vec2(3, 4)});
  EXPECT_FALSE(hub.reports().basket);
  EXPECT_TRUE(link.report_collected({}, 7)) << link.status().last_error;  // the basket alone
  ASSERT_TRUE(hub.reports().basket);
  EXPECT_EQ(hub.reports().basket->value, 7);
  EXPECT_EQ(hub.collected().size(), 1u);
  EXPECT_TRUE(link.report_unreachable({Vec2(5, 1)}, "stuck")) << link.status().last_error;
  ASSERT_EQ(hub.reports().unreachable.size(), 1u);
  EXPECT_EQ(hub.reports().unreachable[0].reason, "stuck");
  EXPECT_TRUE(link.set_pose({Vec2(-2, 1), 0.0}));
  ASSERT_TRUE(hub.robot());
  EXPECT_EQ(hub.robot()->value.position, Vec2(-2, 1));
  EXPECT_FALSE(link.acknowledge(99));  // never published: refused, and said why
  EXPECT_NE(link.status().last_error.find("409"), std::string::npos) << link.status().last_error;
}

TEST_P(RobotLinkTransports, ResumesAfterTheServiceComesBackAndFollowsANewRun) {
  NavigationHub hub;
  ApiContext context{hub, {"ne"}, SiteCourt{}, 0.0335};
  auto server = std::make_unique<HttpServer>(server_options(), api_v1_routes(context));
  const unsigned short port = server->port();
  hub.publish(update(0));
  HttpRobotLink link(link_options(port, GetParam()));
  EXPECT_EQ(test::take(link, 1), test::seq_range(1, 1));  // a new client starts at the latest
  for (int k = 0; k < 4; ++k) hub.publish(update(k));
  EXPECT_EQ(test::take(link, 4), test::seq_range(2, 5));
  // The service goes away; the pipeline publishes on; the same run comes back on the same port.
  server.reset();
  for (int k = 0; k < 5; ++k) hub.publish(update(k));
  std::this_thread::sleep_for(milliseconds(100));
  server = std::make_unique<HttpServer>(server_options(port), api_v1_routes(context));
  EXPECT_EQ(test::take(link, 5), test::seq_range(6, 10));  // nothing lost, nothing twice
  EXPECT_GE(link.status().reconnects, 1);
  // A new run of the service (its seq begins again) is followed from its latest update.
  server.reset();
  NavigationHub restarted;
  ApiContext context2{restarted, {"ne"}, SiteCourt{}, 0.0335};
  restarted.publish(update(0));
  server = std::make_unique<HttpServer>(server_options(port), api_v1_routes(context2));
  const std::optional<LinkUpdate> u = link.next(milliseconds(5000));
  ASSERT_TRUE(u);
  EXPECT_EQ(u->seq, 1u);
  EXPECT_EQ(u->service_id, restarted.service_id());
  for (int k = 0; k < 2; ++k) restarted.publish(update(k));
  EXPECT_EQ(test::take(link, 2), test::seq_range(2, 3));
  EXPECT_EQ(link.status().gaps, 0u);
  server.reset();  // before the run it serves (declared after it) goes
}

INSTANTIATE_TEST_SUITE_P(StreamAndLongPoll, RobotLinkTransports, testing::Bool(),
                         [](const auto& p) { return p.param ? "Stream" : "LongPoll"; });

TEST(RobotLink, OptionsFromAUrlAndBadUpdatesAreNamed) {
  const RobotLinkOptions o = RobotLinkOptions::from_url("http://10.0.0.7:8080/", "--server");
  EXPECT_EQ(o.host, "10.0.0.7");
  EXPECT_EQ(o.port, 8080);
  EXPECT_EQ(RobotLinkOptions::from_url("localhost:9", "--server").host, "localhost");
  EXPECT_THROW(RobotLinkOptions::from_url("http://host", "--server"), InputError);
  EXPECT_THROW(RobotLinkOptions::from_url("http://host:70000", "--server"), InputError);
  try {
    parse_link_update({{"seq", 1u}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("update.service_id"), std::string::npos) << e.what();
  }
}

TEST(RobotLink, AnUpdateCarriesTheObstacles) {
  const nlohmann::json update = {
      {"seq", 3u},
      {"service_id", "s"},
      {"capture_time_ns", 1},
      {"published_ns", 2},
      {"world",
       {{"balls", nlohmann::json::array()},
        {"obstacles", {{{"x_m", 4.0}, {"y_m", -1.0}, {"radius_m", 0.3}, {"outline_m", {}}}}}}},
      {"route", {{"waypoints_m", nlohmann::json::array()}, {"visits_m", nlohmann::json::array()}}}};
  const LinkUpdate u = parse_link_update(update);
  ASSERT_EQ(u.obstacles.size(), 1u);
  EXPECT_EQ(u.obstacles[0].center_m, Vec2(4.0, -1.0));
  EXPECT_EQ(u.obstacles[0].radius_m, 0.3);
  nlohmann::json bad = update;
  bad["world"]["obstacles"][0]["radius_m"] = -1;
  try {
    parse_link_update(bad);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("update.world.obstacles[0].radius_m"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ballsight
