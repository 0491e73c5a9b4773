#include "ballsight/net/api.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "api_error.hpp"
#include "ballsight/net/calibration/court_calibration_api.hpp"
#include "ballsight/net/calibration/omni_calibration_api.hpp"
#include "example_site.hpp"
#include "field_cameras.hpp"
#include "sample_update.hpp"

namespace ballsight {
namespace {

using test::expect_error;

using nlohmann::json;

/// API v1 and the calibration pages' APIs, registered as the service (apps/ballsight/
/// http_service.cpp) registers them; requests go through their routes, as the server sends them.
struct Fixture {
  Fixture() {
    omni.register_routes(routes);
    court_calibration.register_routes(routes);
    context.planner = [this] { return planner; };
    context.set_planner = [this](PlannerKind kind) { planner = kind; };
    context.camera_view = [](std::size_t camera) -> std::optional<CameraView> {
      if (camera != 1) return std::nullopt;  // only "se" has delivered a frame
      CameraView view;
      view.frame = cv::Mat(720, 1280, CV_8UC3, cv::Scalar(40, 120, 60));
      PixelDetection ball;
      ball.center_px = Vec2(640.5, 200.25);
      ball.radius_px = 3.5;
      view.detections.push_back(ball);
      view.seq = 7;
      view.capture_ns = 123;
      return view;
    };
  }

  NavigationHub hub;
  OmniCalibrationApi omni;
  CourtCalibrationApi court_calibration{[] {
    CourtCalibrationApiOptions o;
    o.site = read_site(test::kExampleSite.string());
    o.intrinsics.assign(o.site.cameras.size(),
                        test::overhead_camera({1280, 720}, 900.0, 5.0).camera.params());
    o.latest_frame = [](std::size_t) { return std::nullopt; };  // no frame yet
    return o;
  }()};
  PlannerKind planner = PlannerKind::ballsight;
  ApiContext context{hub, {"ne", "se", "sw", "nw"}, SiteCourt{}, 0.0335};
  ApiRoutes routes = api_v1_routes(context);

  ApiResponse call(const std::string& method, const std::string& target,
                   const std::string& body = "", bool authorized = true) {
    return routes.answer({method, target, body, authorized});
  }
};

NavigationUpdate update_with_robot(double x) {
  return test::sample_update({Vec2(x, 1.0), 0.5});
}

TEST(Api, TheReportsFourMethodsAndItsFlag) {
  Fixture f;
  expect_error(f.call("GET", "/api/v1/robot"), 404, "robot");
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation").body)["latest_seq"], 0);
  f.hub.publish(update_with_robot(2.0));
  // Get robot location, get balls (the cameras').
  const json robot = json::parse(f.call("GET", "/api/v1/robot").body);
  EXPECT_EQ(robot["x_m"], 2.0);
  EXPECT_EQ(robot["source"], "cameras");
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/balls").body)["balls"][0]["y_m"], 4.0);
  // Set robot location and balls (an external localisation or detector): newer, so they win.
  EXPECT_EQ(f.call("PUT", "/api/v1/robot", R"({"x_m": -3, "y_m": 2, "heading_deg": 90})").status,
            200);
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/robot").body)["source"], "external");
  EXPECT_EQ(f.call("PUT", "/api/v1/balls", R"({"balls": [{"x_m": 1, "y_m": 1}]})").status, 200);
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/balls").body)["balls"].size(), 1u);
  // The flag: the robot acknowledges update 1.
  EXPECT_EQ(f.call("POST", "/api/v1/navigation/ack", R"({"seq": 1})").status, 200);
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation").body)["acknowledged_seq"], 1);
  expect_error(f.call("POST", "/api/v1/navigation/ack", R"({"seq": 7})"), 409, "body.seq");
  // Collected balls are kept for the planner.
  EXPECT_EQ(f.call("POST", "/api/v1/collected", R"({"balls": [{"x_m": 3, "y_m": 4}]})").status,
            200);
  EXPECT_EQ(f.hub.collected(), std::vector<Vec2>{Vec2(3, 4)});
  // Or by the ball's index in an update's world model.
  EXPECT_EQ(f.call("POST", "/api/v1/collected", R"({"seq": 1, "ids": [0]})").status, 200);
  EXPECT_EQ(f.hub.collected().size(), 2u);
  expect_error(f.call("POST", "/api/v1/collected", R"({"seq": 1, "ids": [5]})"), 422,
               "body.ids[0]");
  expect_error(f.call("POST", "/api/v1/collected", R"({"seq": 9, "ids": [0]})"), 409, "body.seq");
  expect_error(f.call("POST", "/api/v1/collected", R"({"ids": [0]})"), 400, "body.seq");
  // With the balls in the robot's basket now (0 after emptying it, no ball).
  EXPECT_EQ(f.call("POST", "/api/v1/collected", R"({"seq": 1, "ids": [0], "held": 12})").status,
            200);
  EXPECT_EQ(f.hub.reports().basket->value, 12);
  EXPECT_EQ(f.call("POST", "/api/v1/collected", R"({"balls": [], "held": 0})").status, 200);
  EXPECT_EQ(f.hub.reports().basket->value, 0);
  expect_error(f.call("POST", "/api/v1/collected", R"({"balls": [], "held": -1})"), 400,
               "body.held");
  expect_error(f.call("POST", "/api/v1/collected", R"({"balls": [], "held": 2.5})"), 400,
               "body.held");
  expect_error(f.call("PUT", "/api/v1/balls", R"({"balls": [], "held": 0})"), 400, "body");
  // A ball the robot gave up on, with why; a reason is required.
  EXPECT_EQ(f.call("POST", "/api/v1/unreachable",
                   R"({"balls": [{"x_m": 5, "y_m": 1}], "reason": "stuck at the post"})")
                .status,
            200);
  ASSERT_EQ(f.hub.reports().unreachable.size(), 1u);
  EXPECT_EQ(f.hub.reports().unreachable[0].position_m, Vec2(5, 1));
  EXPECT_EQ(f.hub.reports().unreachable[0].reason, "stuck at the post");
  expect_error(f.call("POST", "/api/v1/unreachable", R"({"balls": [{"x_m": 5, "y_m": 1}]})"), 400,
               "body.reason");
  expect_error(
      f.call("POST", "/api/v1/unreachable", R"({"balls": [{"x_m": 50, "y_m": 1}], "reason": "x"})"),
      422, "body.balls[0]");
}

TEST(Api, LongPollAnswersTheFirstNewerUpdateOrAsksTheTransportToWait) {
  Fixture f;
  f.hub.publish(update_with_robot(1.0));
  const ApiResponse first = f.call("GET", "/api/v1/navigation?after=0&timeout_ms=10");
  EXPECT_FALSE(first.retry);
  const json now = json::parse(first.body);
  EXPECT_EQ(now["seq"], 1);
  EXPECT_EQ(now["service_id"], f.hub.service_id());
  EXPECT_GT(now["published_ns"].get<std::int64_t>(), 0);
  EXPECT_EQ(now["route"]["order"], json({0}));
  // Nothing newer than 1: the transport parks the request (the HTTP server's test waits).
  const ApiResponse pending = f.call("GET", "/api/v1/navigation?after=1&timeout_ms=20");
  EXPECT_EQ(pending.status, 204);
  ASSERT_TRUE(pending.retry);
  EXPECT_EQ(pending.wait.count(), 20);
  EXPECT_EQ(f.call("GET", "/api/v1/navigation?after=1&timeout_ms=99999999").wait.count(), 30000);
  EXPECT_FALSE(pending.retry());
  f.hub.publish(update_with_robot(2.0));
  const std::optional<ApiResponse> answer = pending.retry();
  ASSERT_TRUE(answer);
  EXPECT_EQ(json::parse(answer->body)["seq"], 2);
}

TEST(Api, AClientOfAnEarlierRunOfTheServiceStartsAgainFromTheLatest) {
  Fixture f;
  for (int k = 0; k < 3; ++k) f.hub.publish(update_with_robot(k));
  const std::string mine = "&service=" + f.hub.service_id();
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation?after=2" + mine).body)["seq"], 3);
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation?after=40&service=0f0f").body)["seq"], 3);
  const auto s =
      stream_subscription({"GET", "/api/v1/stream?after=40&service=0f0f", "", false}, f.context);
  EXPECT_EQ(std::get<StreamSubscription>(s).after, 2u);
}

TEST(Api, TheSiteDescribesTheCourt) {
  Fixture f;
  const json site = json::parse(f.call("GET", "/api/v1/site").body);
  EXPECT_EQ(site["court"]["length_m"], f.context.court.length_m);
  EXPECT_EQ(site["court"]["area_width_m"], f.context.court.area_width_m);
  EXPECT_EQ(site["cameras"], json(f.context.camera_names));
  EXPECT_EQ(site["ball_radius_m"], f.context.ball_radius_m);
  EXPECT_FALSE(site["simulated"]);
  EXPECT_EQ(f.call("PUT", "/api/v1/site").status, 405);
}

TEST(Api, TheStreamTakesTopics) {
  Fixture f;
  const auto sub = [&](const std::string& target) {
    return stream_subscription({"GET", target, "", false}, f.context);
  };
  const StreamSubscription plain = std::get<StreamSubscription>(sub("/api/v1/stream"));
  EXPECT_TRUE(plain.navigation);
  EXPECT_FALSE(plain.world || plain.health);
  const StreamSubscription chosen =
      std::get<StreamSubscription>(sub("/api/v1/stream?after=3&topics=world,health"));
  EXPECT_EQ(chosen.after, 3u);
  EXPECT_FALSE(chosen.navigation);
  EXPECT_TRUE(chosen.world && chosen.health);
  // As a browser's URLSearchParams writes it.
  const StreamSubscription encoded =
      std::get<StreamSubscription>(sub("/api/v1/stream?topics=navigation%2Chealth&after=%32"));
  EXPECT_EQ(encoded.after, 2u);
  EXPECT_TRUE(encoded.navigation && encoded.health);
  EXPECT_FALSE(encoded.world);
  expect_error(std::get<ApiResponse>(sub("/api/v1/stream?topics=navigation,weather")), 400,
               "query topics");
  expect_error(std::get<ApiResponse>(sub("/api/v1/stream?topics=%zz")), 400, "query topics");
  expect_error(std::get<ApiResponse>(sub("/api/v1/stream?after=-1")), 400, "query after");
  f.hub.publish(update_with_robot(1.0));
  const json world = json::parse(world_message(*f.hub.latest(), f.context));
  EXPECT_EQ(world["topic"], "world");
  EXPECT_EQ(world["seq"], 1);
  EXPECT_EQ(world["world"]["balls"].size(), 1u);
  EXPECT_EQ(json::parse(navigation_message(*f.hub.latest(), f.context))["update"]["seq"], 1);
  f.context.health = [] { return json{{"frame_sets", 7}}; };
  EXPECT_EQ(json::parse(health_message(f.context))["health"]["frame_sets"], 7);
}

TEST(Api, LongPollGivesTheFirstUpdateNewerThanAfterNotTheLatest) {
  Fixture f;
  for (int k = 0; k < 3; ++k) f.hub.publish(update_with_robot(k));
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation?after=1&timeout_ms=0").body)["seq"], 2);
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation?after=2&timeout_ms=0").body)["seq"], 3);
  // A client that has read nothing yet wants the present: the latest.
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation?after=0&timeout_ms=0").body)["seq"], 3);
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/navigation").body)["latest_seq"], 3);
}

TEST(Api, BadRequestsGetAnErrorNamingWhere) {
  Fixture f;
  expect_error(f.call("GET", "/api/v2/robot"), 404, "/api/v2/robot");
  expect_error(f.call("DELETE", "/api/v1/robot"), 405, "/api/v1/robot");
  expect_error(f.call("PUT", "/api/v1/robot", R"({"x_m": 1})", false), 401, "headers");
  expect_error(f.call("PUT", "/api/v1/robot", "{oops"), 400, "body");
  expect_error(f.call("PUT", "/api/v1/robot", "[1, 2]"), 400, "body");
  expect_error(f.call("PUT", "/api/v1/robot", R"({"x_m": 1, "y_m": 2})"), 400, "body");
  expect_error(f.call("PUT", "/api/v1/robot", R"({"x_m": "1", "y_m": 2, "heading_deg": 0})"), 400,
               "body.x_m");
  expect_error(f.call("PUT", "/api/v1/robot", R"({"x_m": 1, "y_m": 2, "heading_deg": 0, "z": 1})"),
               400, "body");
  expect_error(f.call("PUT", "/api/v1/robot", R"({"x_m": 100, "y_m": 2, "heading_deg": 0})"), 422,
               "body");
  expect_error(f.call("PUT", "/api/v1/balls", R"({"balls": [{"x_m": 1, "y_m": NaN}]})"), 400,
               "body");  // JSON has no NaN: malformed
  expect_error(f.call("PUT", "/api/v1/balls", R"({"balls": [{"x_m": 1}]})"), 400, "body.balls[0]");
  expect_error(f.call("POST", "/api/v1/navigation/ack", R"({"seq": -1})"), 400, "body.seq");
  expect_error(f.call("GET", "/api/v1/navigation?after=x"), 400, "query after");
  expect_error(f.call("GET", "/api/v1/world"), 503, "service");
  expect_error(f.call("GET", "/api/v1/route"), 503, "service");
}

TEST(Api, ThePlannerIsChosenWithTheToken) {
  Fixture f;
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/planner").body)["planner"], "ballsight");
  expect_error(f.call("PUT", "/api/v1/planner", R"({"planner": "nearest"})", false), 401,
               "headers");
  EXPECT_EQ(f.planner, PlannerKind::ballsight);
  expect_error(f.call("PUT", "/api/v1/planner", R"({"planner": "exact"})"), 422, "body.planner");
  expect_error(f.call("PUT", "/api/v1/planner", R"({"planner": 3})"), 400, "body.planner");
  expect_error(f.call("PUT", "/api/v1/planner", R"({"planer": "nearest"})"), 400, "body");
  EXPECT_EQ(f.planner, PlannerKind::ballsight);
  const json chosen =
      json::parse(f.call("PUT", "/api/v1/planner", R"({"planner": "nearest"})").body);
  EXPECT_EQ(chosen["planner"], "nearest");
  EXPECT_EQ(f.planner, PlannerKind::nearest);
  f.context.planner = nullptr;
  expect_error(f.call("GET", "/api/v1/planner"), 404, "planner");
}

TEST(Api, ACamerasLastFrameAndItsDetections) {
  Fixture f;
  const ApiResponse r = f.call("GET", "/api/v1/cameras/se/view");
  ASSERT_EQ(r.status, 200) << r.body;
  const json view = json::parse(r.body);
  EXPECT_EQ(view["seq"], 7);
  EXPECT_EQ(view["width"], 1280);
  EXPECT_EQ(view["detections"][0]["x_px"], 640.5);
  EXPECT_EQ(view["detections"][0]["object"], "ball");
  const std::string prefix = "data:image/jpeg;base64,";
  ASSERT_EQ(view["image"].get<std::string>().rfind(prefix, 0), 0u);
  EXPECT_EQ(view["image"].get<std::string>().substr(prefix.size(), 4), "/9j/");  // FF D8 FF
  expect_error(f.call("GET", "/api/v1/cameras/ne/view"), 404, "camera ne");
  expect_error(f.call("GET", "/api/v1/cameras/centre/view"), 404, "camera centre");
  expect_error(f.call("GET", "/api/v1/cameras/se/frame"), 404, "/api/v1/cameras/se/frame");
  expect_error(f.call("PUT", "/api/v1/cameras/se/view"), 405, "/api/v1/cameras/se/view");
}

TEST(Api, TheCourtCalibrationRoutesAreServed) {
  Fixture f;
  const json site = json::parse(f.call("GET", "/api/v1/court-calibration/site").body);
  EXPECT_EQ(site["cameras"].size(), 4u);
  EXPECT_EQ(site["references"].size(), 12u);
  expect_error(f.call("POST", "/api/v1/court-calibration/stills", R"({"camera": "ne"})"), 409,
               "camera ne");
  EXPECT_TRUE(f.routes.runs_long("/api/v1/court-calibration/site"));
  EXPECT_TRUE(f.routes.runs_long("/api/v1/cameras/ne/view"));
  EXPECT_TRUE(f.routes.runs_long("/api/v1/omni/fits?x=1"));
  EXPECT_FALSE(f.routes.runs_long("/api/v1/navigation?after=3"));
}

TEST(Api, TheOpenApiDocumentListsExactlyTheRoutesThatAnswer) {
  Fixture f;
  f.hub.publish(update_with_robot(1.0));
  const json& doc = openapi_document();
  EXPECT_EQ(json::parse(f.call("GET", "/api/v1/openapi.json").body), doc);
  int operations = 0;
  for (const auto& [path, item] : doc["paths"].items()) {
    for (const auto& [method, operation] : item.items()) {
      std::string upper = method;
      for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      const ApiResponse r = f.call(upper, path, "{}");
      const std::string status = std::to_string(r.status);
      EXPECT_TRUE(operation["responses"].contains(status))
          << upper << " " << path << " answered " << status << " " << r.body;
      ++operations;
    }
    // Every other method is refused.
    for (const char* method : {"GET", "PUT", "POST", "DELETE", "PATCH"}) {
      std::string lower = method;
      for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (item.contains(lower)) continue;
      EXPECT_EQ(f.call(method, path).status, 405) << method << " " << path;
    }
  }
  EXPECT_EQ(operations, 36);
}

}  // namespace
}  // namespace ballsight
