// The closed loop end to end: `serve --sim` with 10 balls and `robot` as two processes on
// loopback; the robot, knowing only what the service sends, collects every ball, and the
// recorded truth shows it never overlapped the net or left the fenced area.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/run_cli.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "ballsight/sim/robot_motion.hpp"
#include "serve_process.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

TEST(LoopCli, TheRobotCollectsEveryBallDrivenByTheService) {
  const TempDir temp;
  const std::string token = (temp / "token").string(), truth = (temp / "truth.jsonl").string();
  ServeProcess service({"--sim", "--balls", "10", "--listen", "127.0.0.1:0", "--duration", "200",
                        "--token-file", token, "--truth-out", truth});
  ASSERT_NE(service.port(), 0);
  const std::string port = std::to_string(service.port());
  const CliResult robot = run_cli({"robot", "--server", "http://127.0.0.1:" + port, "--token-file",
                                   token, "--max-time", "120"});
  EXPECT_EQ(robot.exit_code, 0) << robot.stderr_text;
  EXPECT_NE(robot.stdout_text.find("no ball left"), std::string::npos) << robot.stdout_text;
  EXPECT_NE(robot.stdout_text.find("10 collected; 0 stalls; 0 updates missed"), std::string::npos)
      << robot.stdout_text;
  service.kill(SIGTERM);  // the truth file is complete once it has stopped

  const LoopTruth record = read_loop_truth(truth);
  EXPECT_EQ(record.balls.size(), 10u);
  const sim::RobotFootprint footprint = sim::RobotFootprint::of(sim::RobotBox{}, 0.30, 0.70);
  const sim::TennisCourtSpec court;
  std::uint64_t seq = 0;
  for (const TruthTick& t : record.ticks) {
    ASSERT_FALSE(sim::footprint_blocked(footprint, t.world.robot, court)) << t.world.time_s;
    EXPECT_GT(t.seq, seq) << "every tick published an update (reports of collected balls too)";
    seq = t.seq;
  }
  EXPECT_GT(record.ticks.size(), 50u);
  ASSERT_FALSE(record.ticks.empty());
  EXPECT_EQ(record.ticks.back().world.balls_left, 0);
}

// A robot with a real one's command latency and wheel slip, steering ahead by its latency, on
// balls along the fence (reached square to it, and left backwards), with a basket of four.
TEST(LoopCli, EvalLoopScoresEachSystemOnTheTruth) {
  const CliResult r = run_cli({"eval",
                               "loop",
                               "--scenes",
                               "1",
                               "--min-balls",
                               "6",
                               "--max-balls",
                               "6",
                               "--layouts",
                               "along_fence",
                               "--max-time",
                               "90",
                               "--systems",
                               "ballsight",
                               "--command-latency-ms",
                               "100",
                               "--odometry-drift",
                               "0.01",
                               "--capacity",
                               "4",
                               "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(r.stdout_text);
  const nlohmann::json& s = j["systems"]["ballsight"];
  EXPECT_EQ(s["collected_fraction"], 1.0) << s;
  EXPECT_EQ(s["runs"][0]["balls"], 6);
  EXPECT_TRUE(s["runs"][0]["never_overlapped"].get<bool>());
  EXPECT_GT(s["distance_m_mean"].get<double>(), 1.0);
  EXPECT_LT(s["time_s_mean"].get<double>(), 90.0);
  // Four in the basket: it was emptied at the unload point once, at least.
  EXPECT_GE(s["runs"][0]["unloads"].get<int>(), 1) << s;
  EXPECT_EQ(s["time_ratio_to_ballsight"], 1.0);
  EXPECT_EQ(s["runs"][0]["stalls"], 0);
  EXPECT_EQ(s["runs"][0]["layout"], "along_fence");
  EXPECT_TRUE(s["runs"][0].contains("contacts"));
  EXPECT_TRUE(s["runs"][0].contains("dead_reckoned"));
  EXPECT_TRUE(s["runs"][0]["guarded"].is_number_integer());
  // The body's nearest approach to the net or the fence, from the truth: clear of both.
  EXPECT_GT(s["runs"][0]["min_clearance_m"].get<double>(), 0.0);
  // Scene by scene: every ball along the fence reachable, all collected, none timed out.
  ASSERT_EQ(j["scenes"].size(), 1u);
  const nlohmann::json& scene = j["scenes"][0];
  EXPECT_EQ(scene["layout"], "along_fence");
  EXPECT_EQ(scene["reachable"], 6);
  EXPECT_EQ(scene["systems"]["ballsight"]["collected"], 6);
  EXPECT_EQ(scene["systems"]["ballsight"]["unreachable"], 0);
  EXPECT_FALSE(scene["systems"]["ballsight"]["timed_out"].get<bool>());
  EXPECT_GE(scene["systems"]["ballsight"]["recoveries"].get<int>(), 0);
  expect_one_line_error(run_cli({"eval", "loop", "--systems", "magic"}), "--systems");
  expect_one_line_error(run_cli({"eval", "loop", "--layouts", "square"}), "--layouts");
  expect_one_line_error(run_cli({"eval", "loop", "--odometry-drift", "0.9"}), "--odometry-drift");
  expect_one_line_error(run_cli({"eval", "loop", "--capacity", "0"}), "--capacity");
  expect_one_line_error(run_cli({"eval", "loop", "--command-latency-ms", "-5"}),
                        "--command-latency-ms");
}

}  // namespace
}  // namespace ballsight::test
