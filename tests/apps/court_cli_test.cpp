// `court run` and `eval court` through the command line: a simulated court with its cameras'
// true calibration (court calibrate is tested in calibrate_cli_test.cpp), bad frames and a camera
// that cannot be opened.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "apps/run_cli.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/core/file_io.hpp"
#include "simulated_site.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace fs = std::filesystem;

std::vector<nlohmann::json> json_lines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(nlohmann::json::parse(line));
  return out;
}

TEST(CourtRunCli, WorldModelPerFrameSet) {
  const TempDir temp;
  const fs::path site = simulated_site(temp);
  const CliResult r = run_cli({"court", "run", "--site", site.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto sets = json_lines(r.stdout_text);
  ASSERT_EQ(sets.size(), 2u) << r.stdout_text;
  for (size_t k = 0; k < sets.size(); ++k) {
    SCOPED_TRACE("frame set " + std::to_string(k));
    const nlohmann::json& set = sets[k];
    const nlohmann::json truth = nlohmann::json::parse(
        read_file(site.parent_path() / ("court_000" + std::to_string(k) + ".json")));
    int true_balls = 0;
    for (const auto& o : truth["objects"]) true_balls += o["kind"] == "tennis_ball";
    EXPECT_EQ(set["frame_set"], k);
    EXPECT_EQ(set["cameras"], nlohmann::json({"ne", "se", "sw", "nw"}));
    EXPECT_NEAR(static_cast<double>(set["balls"].size()), true_balls, 0.05 * true_balls + 1);
    EXPECT_FALSE(set["sites"].empty());
    ASSERT_FALSE(set["robot"].is_null());
    const auto& robot = truth["robot"]["position_m"];
    EXPECT_NEAR(set["robot"]["x_m"].get<double>(), robot[0].get<double>(), 0.02);
    EXPECT_NEAR(set["robot"]["y_m"].get<double>(), robot[1].get<double>(), 0.02);
    for (const char* name : kNames) {
      EXPECT_EQ(set["frames"][name]["sequence"], k);
      EXPECT_TRUE(set["frames"][name]["used"].get<bool>());
    }
  }
  const CliResult text = run_cli({"court", "run", "--site", site.string(), "--frames", "1"});
  ASSERT_EQ(text.exit_code, 0) << text.stderr_text;
  EXPECT_EQ(text.stdout_text.rfind("frame set 0: cameras ne,se,sw,nw; ", 0), 0u)
      << text.stdout_text;
  EXPECT_EQ(text.stdout_text.find("frame set 1"), std::string::npos);
}

// A frame of another size than its calibration is not used (and said so), a camera that cannot be
// opened is retried while the others go on; the world model names the cameras that contributed.
TEST(CourtRunCli, BadFramesAndDeadCamerasAreReportedAndTheRestGoesOn) {
  const TempDir temp;
  const fs::path site = simulated_site(temp);
  const fs::path dir = site.parent_path();
  cv::imwrite((dir / "cam2" / "court_0000_cam2.png").string(),
              cv::Mat(480, 640, CV_8UC3, cv::Scalar(70, 128, 88)));
  std::string text = read_file(site);
  const std::string nw = "{folder: cam3}";
  text.replace(text.find(nw), nw.size(), "{device: 97}");
  write_file_atomic(site, text);
  const CliResult r = run_cli(
      {"court", "run", "--site", site.string(), "--json", "--frames", "2", "--wait", "0.5"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("camera sw: frame is 640x480 but the camera's calibration is for "
                               "1280x720; frame not used"),
            std::string::npos)
      << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("camera nw: cannot open video device 97; retrying in"),
            std::string::npos)
      << r.stderr_text;
  const auto sets = json_lines(r.stdout_text);
  ASSERT_EQ(sets.size(), 2u) << r.stdout_text;
  EXPECT_EQ(sets[0]["cameras"], nlohmann::json({"ne", "se"}));
  EXPECT_FALSE(sets[0]["frames"]["sw"]["used"].get<bool>());
  EXPECT_TRUE(sets[0]["frames"]["nw"].is_null());
  EXPECT_EQ(sets[1]["cameras"], nlohmann::json({"ne", "se", "sw"}));
  EXPECT_FALSE(sets[1]["balls"].empty());
}

TEST(CourtRunCli, BadSitesFailWithOneLine) {
  const TempDir temp;
  expect_one_line_error(run_cli({"court", "run", "--site", (temp / "none.yml").string()}),
                        "none.yml");
  const fs::path site = simulated_site(temp);
  fs::remove(site.parent_path() / "cam1.yml");
  expect_one_line_error(run_cli({"court", "run", "--site", site.string()}), "cam1.yml");
  expect_one_line_error(run_cli({"court", "run", "--site", site.string(), "--frames", "-1"}),
                        "--frames");
}

// `eval court`: both methods calibrated from rendered images, the JSON shape the lead's report
// reads, and the pictures.
TEST(EvalCourtCli, JsonShapeAndPictures) {
  const TempDir temp;
  // At 1280 x 720: the chessboard calibration of seed 3 takes minutes at 1920 x 1080.
  const CliResult r = run_cli({"eval", "court", "--json", "--scenes", "1", "--seed", "3", "--width",
                               "1280", "--height", "720", "--plot-dir", (temp / "plots").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(r.stdout_text);
  for (const char* method : {"seed", "ballsight"}) {
    SCOPED_TRACE(method);
    const nlohmann::json& m = j["methods"][method];
    for (const char* key : {"recall", "precision", "ball_error_mean_cm", "ball_error_p95_cm",
                            "robot_position_error_cm", "robot_heading_error_deg"})
      EXPECT_TRUE(m[key].is_number()) << key;
    EXPECT_TRUE(m["duplicates"].is_number_integer());
    // Every ball the method got wrong, one entry each: the counts add up.
    ASSERT_TRUE(m["mistakes"].is_array());
    std::map<std::string, int> kinds;
    for (const nlohmann::json& mistake : m["mistakes"]) {
      EXPECT_EQ(mistake["scene"], 0);
      EXPECT_TRUE(mistake["x_m"].is_number() && mistake["y_m"].is_number());
      ++kinds[mistake["kind"].get<std::string>()];
    }
    EXPECT_EQ(kinds["missed"], m["balls_counted"].get<int>() - m["true_positives"].get<int>());
    EXPECT_EQ(kinds["duplicate"], m["duplicates"].get<int>());
    EXPECT_EQ(kinds["false_positive"], m["false_positives"].get<int>());
    EXPECT_EQ(kinds.size(), 3u);  // no other kind
  }
  EXPECT_GT(j["methods"]["ballsight"]["recall"].get<double>(),
            j["methods"]["seed"]["recall"].get<double>());
  for (const char* picture : {"scene_0000_cam0.png", "scene_0000_cam3.png", "scene_0000_field.png"})
    EXPECT_TRUE(fs::exists(temp / "plots" / picture)) << picture;
  expect_one_line_error(run_cli({"eval", "court", "--scenes", "0"}), "scenes");
  expect_one_line_error(run_cli({"eval", "court", "--plot-mistakes"}), "--plot-dir");
  expect_one_line_error(run_cli({"eval", "court", "--camera-height-m", "5,1"}),
                        "--camera-height-m");
  expect_one_line_error(run_cli({"eval", "tennis-sim", "--jpeg-quality", "101"}), "--jpeg-quality");
}

}  // namespace
}  // namespace ballsight::test
