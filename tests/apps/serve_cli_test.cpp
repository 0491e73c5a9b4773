// `ballsight serve --sim` end to end: the service on a free loopback port, a client that
// long-polls the route, reports the first ball collected and sees it leave the plan and the court.
#include <gtest/gtest.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "apps/run_cli.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "http_request.hpp"
#include "simulated_site.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using nlohmann::json;

/// `ballsight serve ARGS --listen 127.0.0.1:0`, its stdout read through `out`; its port.
unsigned short start_serve(const std::string& args, FILE*& out) {
  const std::string command =
      std::string("'") + BALLSIGHT_CLI + "' serve --listen 127.0.0.1:0 " + args;
  out = ::popen(command.c_str(), "r");
  if (out == nullptr) return 0;
  char line[256] = {};
  if (std::fgets(line, sizeof line, out) == nullptr) return 0;
  const std::string first(line);
  const std::size_t colon = first.find("127.0.0.1:");
  return colon == std::string::npos
             ? 0
             : static_cast<unsigned short>(std::stoi(first.substr(colon + 10)));
}

/// The rest of the service's output, once it stopped; its exit status in `status`.
std::string rest_of(FILE* out, int& status) {
  std::string rest;
  char line[256] = {};
  while (std::fgets(line, sizeof line, out) != nullptr) rest += line;
  status = ::pclose(out);
  return rest;
}

TEST(ServeCli, SimulatedCourtRouteAndCollectedBall) {
  const TempDir temp;
  const std::string token_file = (temp / "token").string();
  FILE* out = nullptr;
  const unsigned short port =
      start_serve("--sim --rate 5 --duration 12 --token-file '" + token_file + "'", out);
  ASSERT_NE(port, 0);
  const std::string token = read_file(token_file).substr(0, 32);

  const Reply u1 = request(port, http::verb::get, "/api/v1/navigation?after=0&timeout_ms=8000");
  ASSERT_EQ(u1.status, 200);
  const json& route = u1.body["route"];
  const json& balls = u1.body["world"]["balls"];
  ASSERT_GT(balls.size(), 10u);
  ASSERT_FALSE(route["order"].empty());
  EXPECT_GE(u1.body["published_ns"].get<std::int64_t>(),
            u1.body["capture_time_ns"].get<std::int64_t>());
  const json target = balls[route["order"][0].get<std::size_t>()];
  const double tx = target["x_m"], ty = target["y_m"];

  EXPECT_EQ(request(port, http::verb::post, "/api/v1/collected",
                    json{{"balls", {{{"x_m", tx}, {"y_m", ty}}}}}.dump())
                .status,
            401);
  ASSERT_EQ(request(port, http::verb::post, "/api/v1/collected",
                    json{{"balls", {{{"x_m", tx}, {"y_m", ty}}}}}.dump(), token)
                .status,
            200);
  // With no robot driving, a hand takes the ball off the court at the next tick (the report's
  // own test): a few updates later the cameras no longer see it (near the robot, the world may
  // still remember it as hidden by the robot, seen by no camera; no route goes there).
  const auto sees_target = [&](const json& update) {
    for (const json& b : update["world"]["balls"]) {
      if (b["cameras"].empty()) continue;
      if (std::hypot(b["x_m"].get<double>() - tx, b["y_m"].get<double>() - ty) < 0.1) return true;
    }
    return false;
  };
  std::uint64_t seq = u1.body["seq"];
  json latest = u1.body;
  for (int k = 0; k < 5 && sees_target(latest); ++k) {
    const Reply u = request(port, http::verb::get,
                            "/api/v1/navigation?after=" + std::to_string(seq) + "&timeout_ms=8000");
    ASSERT_EQ(u.status, 200);
    seq = u.body["seq"];
    latest = u.body;
  }
  EXPECT_FALSE(sees_target(latest));
  for (const json& v : latest["route"]["visits_m"]) {
    EXPECT_GT(std::hypot(v[0].get<double>() - tx, v[1].get<double>() - ty), 0.1);
  }
  EXPECT_EQ(
      request(port, http::verb::post, "/api/v1/navigation/ack", json{{"seq", seq}}.dump(), token)
          .status,
      200);
  EXPECT_EQ(request(port, http::verb::get, "/api/v1/navigation").body["acknowledged_seq"], seq);
  const Reply health = request(port, http::verb::get, "/api/v1/health");
  EXPECT_GE(health.body["frame_sets"].get<int>(), 2) << health.body.dump();  // failures, times
  int status = -1;
  const std::string rest = rest_of(out, status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(rest.find("stopped after"), std::string::npos) << rest;
}

TEST(ServeCli, ACollectedBallLeavesThePlanAtOnce) {
  const TempDir temp;
  const std::string token_file = (temp / "token").string();
  FILE* out = nullptr;  // a frame set every 4 s: an update within 1 s is the re-plan
  const unsigned short port = start_serve(
      "--sim --rate 0.25 --realtime --duration 5 --token-file '" + token_file + "'", out);
  ASSERT_NE(port, 0);
  const Reply u1 = request(port, http::verb::get, "/api/v1/navigation?after=0&timeout_ms=8000");
  ASSERT_EQ(u1.status, 200);
  const json& order = u1.body["route"]["order"];
  ASSERT_FALSE(order.empty());
  const json& ball = u1.body["world"]["balls"][order[0].get<std::size_t>()];
  const json target{{"x_m", ball["x_m"]}, {"y_m", ball["y_m"]}};
  ASSERT_EQ(
      request(port, http::verb::post, "/api/v1/collected",
              json{{"balls", json::array({target})}}.dump(), read_file(token_file).substr(0, 32))
          .status,
      200);
  const Reply u2 = request(
      port, http::verb::get,
      "/api/v1/navigation?after=" + std::to_string(u1.body["seq"].get<int>()) + "&timeout_ms=1000");
  ASSERT_EQ(u2.status, 200);
  EXPECT_EQ(u2.body["capture_time_ns"], u1.body["capture_time_ns"]);  // the same frames, re-planned
  EXPECT_EQ(u2.body["route"]["order"].size() + 1, order.size());
  for (const json& v : u2.body["route"]["visits_m"]) {
    EXPECT_GT(std::hypot(v[0].get<double>() - target["x_m"].get<double>(),
                         v[1].get<double>() - target["y_m"].get<double>()),
              0.1);
  }
  int status = -1;
  rest_of(out, status);
  EXPECT_EQ(status, 0);
}

TEST(ServeCli, TheSitesCamerasRecorded) {
  const TempDir temp;
  const std::filesystem::path site = simulated_site(temp);
  FILE* out = nullptr;
  const unsigned short port =
      start_serve("--site '" + site.string() + "' --duration 8 --token-file '" +
                      (temp / "token").string() + "'",
                  out);
  ASSERT_NE(port, 0);
  // Two recorded frame sets: two updates, the route planned from the robot the cameras saw.
  for (std::uint64_t seq = 1; seq <= 2; ++seq) {
    const Reply u =
        request(port, http::verb::get,
                "/api/v1/navigation?after=" + std::to_string(seq - 1) + "&timeout_ms=8000");
    ASSERT_EQ(u.status, 200);
    EXPECT_EQ(u.body["seq"], seq);
    EXPECT_GT(u.body["world"]["balls"].size(), 3u);
    EXPECT_TRUE(u.body["world"]["robot"].is_object());
    EXPECT_FALSE(u.body["route"]["order"].empty());
  }
  // The recordings have ended: the cameras say so, and the last update stays served.
  EXPECT_EQ(request(port, http::verb::get, "/api/v1/navigation?after=2&timeout_ms=1500").status,
            204);
  const Reply health = request(port, http::verb::get, "/api/v1/health");
  ASSERT_EQ(health.body["cameras"].size(), 4u);
  for (const json& camera : health.body["cameras"]) {
    EXPECT_EQ(camera["state"], "finished") << camera;
    EXPECT_EQ(camera["frames"], 2) << camera;
    EXPECT_TRUE(camera["last_frame_age_s"].is_number()) << camera;
  }
  EXPECT_EQ(health.body["frame_sets"], 2);
  EXPECT_EQ(request(port, http::verb::get, "/api/v1/route").status, 200);
  int status = -1;
  rest_of(out, status);
  EXPECT_EQ(status, 0);
}

// A camera knocked off its pose (its file says 0.6 m elsewhere) is calibrated again from the
// court calibration page's API while the service runs: the file then holds the pose the
// reference balls give (within 3 cm of the camera's true place) and the service takes it.
TEST(ServeCli, TheCourtCalibrationPageReCalibratesARunningSite) {
  const TempDir temp;
  const std::filesystem::path site = simulated_site(temp);
  const std::filesystem::path file = temp / "site" / "cam0.yml";
  CameraCalibration knocked = read_camera_file(file);
  const Vec3 truth = knocked.extrinsics->camera_from_field.inverse().translation;
  knocked.extrinsics->camera_from_field.translation += Vec3(0.6, 0.0, 0.0);
  write_camera_file(file, knocked);
  FILE* out = nullptr;
  const std::string token_file = (temp / "token").string();
  const unsigned short port = start_serve(
      "--site '" + site.string() + "' --duration 8 --token-file '" + token_file + "'", out);
  ASSERT_NE(port, 0);
  ASSERT_EQ(request(port, http::verb::get, "/api/v1/navigation?after=0&timeout_ms=8000").status,
            200);
  const Reply still =
      request(port, http::verb::post, "/api/v1/court-calibration/stills", R"({"camera": "ne"})");
  ASSERT_EQ(still.status, 201) << still.body;
  const std::string save =
      "/api/v1/court-calibration/stills/" + still.body["still"].get<std::string>() + "/calibration";
  EXPECT_EQ(request(port, http::verb::put, save, "{}").status, 401);
  const Reply saved =
      request(port, http::verb::put, save, "{}", read_file(token_file).substr(0, 32));
  ASSERT_EQ(saved.status, 200) << saved.body;
  EXPECT_EQ(saved.body["applied"], true);
  EXPECT_EQ(saved.body["written"], file.string());
  const CameraCalibration fixed = read_camera_file(file);
  EXPECT_LT((fixed.extrinsics->camera_from_field.inverse().translation - truth).norm(), 0.03);
  EXPECT_EQ(request(port, http::verb::get, "/api/v1/health").status, 200);
  int status = -1;
  rest_of(out, status);
  EXPECT_EQ(status, 0);
}

TEST(ServeCli, BadOptionsFailWithOneLine) {
  expect_one_line_error(run_cli({"serve"}), "--site");
  expect_one_line_error(run_cli({"serve", "--sim", "--site", "x.yml"}), "--site");
  expect_one_line_error(run_cli({"serve", "--site", "/nonexistent/site.yml"}), "site.yml");
  expect_one_line_error(run_cli({"serve", "--sim", "--listen", "127.0.0.1"}), "--listen");
  expect_one_line_error(run_cli({"serve", "--sim", "--listen", "nowhere:80"}), "--listen");
  expect_one_line_error(run_cli({"serve", "--sim", "--planner", "exact"}), "--planner");
  expect_one_line_error(run_cli({"serve", "--sim", "--resume"}), "--resume");
  for (const char* bad : {"7@3", "1", "1@x", "1.5@2", "1@-2", "1@5-3", "1@2-x"}) {
    expect_one_line_error(run_cli({"serve", "--sim", "--sim-fail-camera", bad}),
                          "--sim-fail-camera");
  }
  for (const char* malformed : {"1", "x@2", "1@x", "1@2-x"}) {  // the whole option is quoted
    expect_one_line_error(run_cli({"serve", "--sim", "--sim-fail-camera", malformed}),
                          "got '" + std::string(malformed) + "'");
  }
  expect_one_line_error(run_cli({"serve", "--sim", "--cluster-share", "2"}), "--cluster-share");
  expect_one_line_error(run_cli({"serve", "--sim", "--record", "/nonexistent/run.mcap"}),
                        "/nonexistent/run.mcap: cannot open for writing");
  expect_one_line_error(
      run_cli({"serve", "--sim", "--record", "run.mcap", "--record-compression", "gzip"}),
      "--record-compression");
  expect_one_line_error(run_cli({"serve", "--sim", "--record", "run.mcap", "--record-every", "-1"}),
                        "--record-every");
  expect_one_line_error(run_cli({"record", "info", "/nonexistent/run.mcap"}),
                        "/nonexistent/run.mcap: cannot open");
  // A record of another scene is not resumed.
  const TempDir temp;
  const std::string record = (temp / "truth.jsonl").string();
  write_file_atomic(record, scene_record(9, {}, Pose2D{}).dump() + "\n");
  expect_one_line_error(
      run_cli({"serve", "--sim", "--seed", "1", "--truth-out", record, "--resume"}), "seed 9");
}

}  // namespace
}  // namespace ballsight::test
