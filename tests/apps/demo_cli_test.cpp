#include <gtest/gtest.h>

#include <filesystem>

#include "apps/run_cli.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace fs = std::filesystem;

TEST(DemoCli, WritesAReportThatShowsEveryImage) {
  const TempDir dir;
  const fs::path out = dir / "demo";
  const CliResult r =
      run_cli({"demo", "--out", out.string(), "--omni-frames", "2", "--loop-balls", "10"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const std::string html = read_file(out / "report.html");
  int images = 0;
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    if (entry.path().extension() != ".png") continue;
    ++images;
    const std::string relative = fs::relative(entry.path(), out).string();
    EXPECT_NE(html.find("src=\"" + relative + "\""), std::string::npos) << relative;
  }
  // Two omni frames, four court views, the court evaluation's four views and field map, the
  // collection route, and the closed loop's map and latency chart for each of its four runs.
  EXPECT_EQ(images, 2 + 4 + 5 + 1 + 4 * 2);
  const std::string markdown = read_file(out / "report.md");
  EXPECT_NE(markdown.find("calibration markers"), std::string::npos);
  // The omni run time: calibrated from the markers found, the ball placed and scored.
  EXPECT_NE(markdown.find("324 of 324 markers found in frame 0"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("ballsight: error "), std::string::npos) << markdown;
  EXPECT_TRUE(fs::exists(out / "omni" / "ballsight.bsgm"));
  // The court evaluation: both methods scored.
  EXPECT_NE(markdown.find("\n| ballsight | "), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("\n| seed | "), std::string::npos) << markdown;
  EXPECT_EQ(markdown.find("wrote "), std::string::npos) << markdown;
  // The route: the three planners, ballsight's the fastest.
  const std::size_t route = markdown.find("## Court: collection route");
  ASSERT_NE(route, std::string::npos) << markdown;
  const auto seconds = [&](const std::string& planner) {
    const std::string row = "\n| " + planner + " | ";
    const std::size_t at = markdown.find(row, route);
    EXPECT_NE(at, std::string::npos) << planner;
    return at == std::string::npos ? 0.0 : std::stod(markdown.substr(at + row.size()));
  };
  EXPECT_LT(seconds("ballsight"), seconds("nearest"));
  EXPECT_LT(seconds("nearest"), seconds("priority"));

  // The closed loop, service and robot as processes: ballsight collects all ten, with no update
  // lost at the robot, and so it does through a camera failure and both processes restarted.
  const std::size_t loop = markdown.find("## Court: the closed loop");
  ASSERT_NE(loop, std::string::npos) << markdown;
  const auto row = [&](const std::string& system) {
    const std::size_t at = markdown.find("\n| " + system + " | ", loop);
    EXPECT_NE(at, std::string::npos) << system;
    return at == std::string::npos ? std::string()
                                   : markdown.substr(at + 1, markdown.find('\n', at + 1) - at - 1);
  };
  EXPECT_NE(row("ballsight").find("10 / 10"), std::string::npos) << row("ballsight");
  EXPECT_NE(row("ballsight-faults").find("10 / 10"), std::string::npos) << markdown;
  EXPECT_EQ(row("report").find("10 / 10"), std::string::npos) << "the report's pipeline misses";
  for (const char* event :
       {"camera 1 failed", "service killed", "the court resumed", "robot killed"}) {
    EXPECT_NE(markdown.find(event, loop), std::string::npos) << event;
  }
  EXPECT_NE(r.stdout_text.find("balls left"), std::string::npos) << "progress while it runs";

  // The report opens with the result, before any section.
  const std::size_t result = markdown.find("## The result");
  EXPECT_LT(result, markdown.find("## Omnidirectional rig"));
  EXPECT_NE(markdown.find("\n| ballsight | 10 of 10 | ", result), std::string::npos) << markdown;
  // The loop replayed in the page, offline: its data and script inline.
  EXPECT_NE(html.find("id=\"loop-replay\""), std::string::npos);
  EXPECT_NE(html.find("id=\"loop-replay-data\""), std::string::npos);
  EXPECT_NE(html.find("startLoopReplay(document"), std::string::npos);
  EXPECT_EQ(html.find("<script type=\"module\" src="), std::string::npos) << "nothing to fetch";
  // Each service's recording, linked: the run with faults had two services (one killed).
  for (const char* file : {"loop/ballsight/run-1.mcap", "loop/ballsight-faults/run-1.mcap",
                           "loop/ballsight-faults/run-2.mcap"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
    EXPECT_NE(html.find(std::string("href=\"") + file + "\""), std::string::npos) << file;
  }
}

TEST(DemoCli, BadOptionsFailWithOneLine) {
  const TempDir dir;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"demo"},
        {"demo", "--out", (dir / "x").string(), "--omni-frames", "0"},
        {"demo", "--out", (dir / "x").string(), "--seed", "abc"},
        {"demo", "--out", (dir / "x").string(), "--seed", "-5"},
        {"demo", "--out", (dir / "x").string(), "--loop-balls", "0"},
        {"demo", "--out", (dir / "x").string(), "--loop-max-time", "-1"}}) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args.back();
    EXPECT_EQ(line_count(r.stderr_text), 1) << r.stderr_text;
  }
  EXPECT_FALSE(fs::exists(dir / "x" / "report.html"));
}

}  // namespace
}  // namespace ballsight::test
