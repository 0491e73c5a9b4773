// The closed loop end to end: `serve --sim` with 10 balls and `robot` as two processes on
// loopback; the robot, knowing only what the service sends, collects every ball, and the
// recorded truth shows it never overlapped the net or left the fenced area.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/run_cli.hpp"
#include "ballsight/core/angle.hpp"
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
  EXPECT_NE(robot.stdout_text.find("10 collected; 0 updates missed"), std::string::npos)
      << robot.stdout_text;
  service.kill(SIGTERM);  // the truth file is complete once it has stopped

  std::ifstream in(truth);
  const sim::RobotFootprint footprint = sim::RobotFootprint::of(sim::RobotBox{}, 0.30, 0.70);
  const sim::TennisCourtSpec court;
  int ticks = 0, balls_left = -1;
  for (std::string row; std::getline(in, row);) {
    const nlohmann::json t = nlohmann::json::parse(row);
    const Pose2D pose{Vec2(t["robot"]["x_m"], t["robot"]["y_m"]),
                      rad_from_deg(t["robot"]["heading_deg"].get<double>())};
    ASSERT_FALSE(sim::footprint_blocked(footprint, pose, court)) << row;
    balls_left = t["balls_left"];
    ++ticks;
  }
  EXPECT_GT(ticks, 50);
  EXPECT_EQ(balls_left, 0);
}

}  // namespace
}  // namespace ballsight::test
