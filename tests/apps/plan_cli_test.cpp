// `ballsight plan`, `eval plan` and `eval tsplib` through the command line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "apps/run_cli.hpp"
#include "ballsight/core/file_io.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace fs = std::filesystem;

const std::string kSite = BALLSIGHT_SOURCE_DIR "/docs/examples/site.yml";

fs::path write(const TempDir& temp, const std::string& name, const std::string& text) {
  write_file_atomic(temp / name, text);
  return temp / name;
}

TEST(PlanCli, RouteOnTheExampleSiteGoesRoundTheNet) {
  const TempDir temp;
  // Balls on both sides of the net, one against it, one beyond the fence.
  const fs::path csv =
      write(temp, "balls.csv", "x_m,y_m\n3,2\n-4,1.5\n5,-3\n-6,-5\n0.05,2\n30,0\n8,4\n-9,-2\n");
  const CliResult r = run_cli({"plan", "--site", kSite, "--balls", csv.string(), "--robot",
                               "-10,0,0", "--json", "--plot", (temp / "route.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(r.stdout_text);
  EXPECT_EQ(j["planner"], "ballsight");
  EXPECT_EQ(j["unreachable"], nlohmann::json({5}));
  std::vector<int> order = j["order"];
  std::sort(order.begin(), order.end());
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4, 6, 7}));
  // Every leg that changes side does so beyond a post (6.4 m from the centre line).
  const auto& w = j["waypoints_m"];
  double length = 0.0;
  for (std::size_t i = 1; i < w.size(); ++i) {
    const double x0 = w[i - 1][0], y0 = w[i - 1][1], x1 = w[i][0], y1 = w[i][1];
    length += std::hypot(x1 - x0, y1 - y0);
    if ((x0 < 0.0) != (x1 < 0.0) && x0 != x1) {
      const double y = y0 + (y1 - y0) * (0.0 - x0) / (x1 - x0);
      EXPECT_GT(std::abs(y), 6.4) << "leg " << i << " crosses the net at y = " << y;
    }
  }
  EXPECT_NEAR(length, j["length_m"].get<double>(), 1e-6);
  EXPECT_GT(j["time_s"].get<double>(), j["length_m"].get<double>());  // 1 m/s and turns
  const cv::Mat plot = cv::imread((temp / "route.png").string());
  EXPECT_GT(plot.cols, 1000);
}

TEST(PlanCli, TheWorldModelGivesTheBallsAndTheRobot) {
  const TempDir temp;
  const fs::path world =
      write(temp, "world.json",
            R"({"balls": [{"x_m": -5, "y_m": 1, "sigma_m": 0.01, "cameras": ["ne"]},
                    {"x_m": -2, "y_m": -3, "sigma_m": 0.01, "cameras": ["ne"]}],
          "sites": [], "robot": {"x_m": -8, "y_m": 0, "heading_deg": 0}})");
  const CliResult r = run_cli({"plan", "--site", kSite, "--world", world.string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stdout_text.find("planner ballsight: 2 balls, 0 out of reach"), std::string::npos)
      << r.stdout_text;
  EXPECT_NE(r.stdout_text.find("order: 0 1"), std::string::npos) << r.stdout_text;
  // The collector mouth, 0.30 m ahead of the robot's reference point, starts the path.
  EXPECT_NE(r.stdout_text.find("  -7.700, 0.000"), std::string::npos) << r.stdout_text;
  const fs::path no_robot =
      write(temp, "no_robot.json", R"({"balls": [{"x_m": 1, "y_m": 1}], "robot": null})");
  expect_one_line_error(run_cli({"plan", "--world", no_robot.string()}),
                        "--robot: needed: the world model has no robot pose");
}

TEST(PlanCli, PlainPointSolverFindsTheSquare) {
  const TempDir temp;
  // The corners of a 3 x 4 rectangle and its centre, from a corner and back: round three sides
  // (3 + 4 + 3), to the centre and back to the start (2.5 + 2.5).
  const fs::path csv = write(temp, "p.csv", "x_m,y_m\n3,0\n3,4\n0,4\n1.5,2\n");
  const CliResult r = run_cli({"plan", "--balls", csv.string(), "--robot", "0,0,0", "--cost",
                               "distance", "--return-to", "0,0", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(r.stdout_text);
  EXPECT_NEAR(j["length_m"].get<double>(), 15.0, 1e-9);
  const CliResult priority = run_cli(
      {"plan", "--balls", csv.string(), "--robot", "0,0,0", "--planner", "priority", "--json"});
  ASSERT_EQ(priority.exit_code, 0) << priority.stderr_text;
  EXPECT_EQ(nlohmann::json::parse(priority.stdout_text)["planner"], "priority");
}

TEST(PlanCli, BadInputFailsWithOneLine) {
  const TempDir temp;
  const std::string good = write(temp, "good.csv", "x_m,y_m\n1,1\n2,2\n").string();
  const std::string bad = write(temp, "bad.csv", "x_m,y_m\n1,1\n2,oops\n").string();
  const std::string nan = write(temp, "nan.csv", "x_m,y_m\nnan,1\n").string();
  const std::string header = write(temp, "header.csv", "x,y\n1,1\n").string();
  const std::string twice = write(temp, "twice.csv", "x_m,y_m\n1,1\n3,3\n1.001,1\n").string();
  const std::string json = write(temp, "w.json", "{\"balls\": [{\"x_m\": 1}]}").string();
  const auto plan = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "plan");
    return run_cli(args);
  };
  expect_one_line_error(plan({"--balls", bad, "--robot", "0,0,0"}), "bad.csv:3:3: y_m");
  expect_one_line_error(plan({"--balls", nan, "--robot", "0,0,0"}), "nan.csv:2:1: x_m");
  expect_one_line_error(plan({"--balls", header, "--robot", "0,0,0"}), "header x_m,y_m");
  expect_one_line_error(plan({"--balls", twice, "--robot", "0,0,0"}),
                        "balls[0] and balls[2]: duplicate ball");
  expect_one_line_error(plan({"--world", json, "--robot", "0,0,0"}), "balls[0].y_m: missing");
  expect_one_line_error(plan({"--balls", good, "--robot", "0.05,3,0", "--site", kSite}),
                        "inside the net");
  expect_one_line_error(
      plan({"--balls", good, "--robot", "0,0,0", "--capacity", "0", "--unload", "1,1"}),
      "--capacity: must be at least 1");
  expect_one_line_error(plan({"--balls", good, "--robot", "0,0,0", "--planner", "fast"}),
                        "--planner");
  expect_one_line_error(plan({"--balls", good, "--world", json, "--robot", "0,0,0"}),
                        "exactly one of");
  expect_one_line_error(plan({"--balls", (temp / "none.csv").string(), "--robot", "0,0,0"}),
                        "none.csv");
}

TEST(EvalPlanCli, SmallSizesMeetTheExactOptimum) {
  const CliResult r = run_cli({"eval", "plan", "--sizes", "5,12", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(r.stdout_text);
  for (const char* n : {"5", "12"}) {
    const auto& ours = j["planners"]["ballsight"]["by_n"][n];
    EXPECT_LT(ours["gap_to_optimal_pct_mean"].get<double>(), 0.5) << n;
    EXPECT_LT(ours["gap_to_optimal_pct_max"].get<double>(), 2.0) << n;
    EXPECT_GE(ours["gap_to_optimal_pct_mean"].get<double>(), -1e-9) << n;  // exact is exact
    EXPECT_GT(j["ballsight_time_saved_pct"]["priority"][n].get<double>(), 0.0) << n;
    // The planning times are wall-clock: apart, at their path.
    EXPECT_FALSE(ours.contains("plan_ms_mean")) << n;
    EXPECT_TRUE(
        j["wall_clock"]["planners"]["ballsight"]["by_n"][n]["plan_ms_mean"].is_number_float());
  }
  // One seed, the same bytes but the wall clock's.
  nlohmann::json again =
      nlohmann::json::parse(run_cli({"eval", "plan", "--sizes", "5,12", "--json"}).stdout_text);
  nlohmann::json first = j;
  first.erase("wall_clock");
  again.erase("wall_clock");
  EXPECT_EQ(again.dump(), first.dump());
  expect_one_line_error(run_cli({"eval", "plan", "--sizes", "5,x"}), "--sizes");
}

TEST(EvalTsplibCli, PublishedOptimaWithinOnePercent) {
  if (!fs::exists("/usr/share/doc/glpk-utils/examples/tsp/bench.txt")) {
    BALLSIGHT_SKIP() << "glpk-utils' TSPLIB examples missing";
  }
  const CliResult r = run_cli({"eval", "tsplib", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(r.stdout_text);
  ASSERT_EQ(j.size(), 4u);
  for (const auto& row : j) EXPECT_LE(row["gap_pct"].get<double>(), 1.0) << row["instance"];
}

}  // namespace
}  // namespace ballsight::test
