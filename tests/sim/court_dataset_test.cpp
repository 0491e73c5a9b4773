#include "ballsight/sim/court_dataset.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight::sim {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

/// Small images keep the test quick; the content is the same kind.
CourtDatasetOptions small_dataset(std::uint64_t seed) {
  CourtDatasetOptions options;
  options.seed = seed;
  options.rig.width = 320;
  options.rig.height = 180;
  options.chessboard_views = 1;
  return options;
}

TEST(CourtDataset, WritesImagesAndTruthNamedAsDocumented) {
  const TempDir dir;
  auto options = small_dataset(4);
  options.scenes = 2;
  const auto files = write_court_dataset(options, dir.path());
  const std::vector<std::string> expected = {
      "court_0000_cam0.png", "court_0000_cam1.png", "court_0000_cam2.png", "court_0000_cam3.png",
      "court_0000.json",     "court_0001_cam0.png", "court_0001_cam1.png", "court_0001_cam2.png",
      "court_0001_cam3.png", "court_0001.json",     "cam0_board_00.png",   "cam1_board_00.png",
      "cam2_board_00.png",   "cam3_board_00.png",   "chessboards.json"};
  EXPECT_EQ(files, expected);
  for (const auto& f : files) EXPECT_TRUE(fs::is_regular_file(dir.path() / f)) << f;
}

TEST(CourtDataset, TruthJsonReprojectsWithOpenCV) {
  const TempDir dir;
  write_court_dataset(small_dataset(5), dir.path());
  const auto truth = nlohmann::json::parse(read_file(dir.path() / "court_0000.json"));
  EXPECT_EQ(truth["format"], "ballsight.sim.court");
  EXPECT_EQ(truth["cameras"].size(), 4u);
  std::map<std::string, int> kinds;
  for (const auto& object : truth["objects"]) kinds[object["kind"]]++;
  EXPECT_GE(kinds["tennis_ball"], 20);
  EXPECT_EQ(kinds["reference_ball"], 12);
  EXPECT_EQ(kinds["robot_front_marker"], 1);
  EXPECT_EQ(kinds["robot_back_marker"], 1);
  // The documented intrinsics and camera_from_field put every object's centre where the JSON says.
  const auto& net = truth["court"]["net"];
  EXPECT_EQ(net["post_positions_m"], nlohmann::json::parse("[[0.0, -6.399], [0.0, 6.399]]"));
  EXPECT_EQ(net["post_height_m"], 1.07);
  EXPECT_EQ(net["centre_height_m"], 0.914);
  EXPECT_EQ(net["post_radius_m"], 0.04);
  EXPECT_EQ(net["band_depth_m"], 0.06);
  int checked = 0, hidden_by_net = 0;
  for (size_t c = 0; c < 4; ++c) {
    const auto& cam = truth["cameras"][c];
    const cv::Matx33d k(cam["fx"], 0, cam["cx"], 0, cam["fy"], cam["cy"], 0, 0, 1);
    const std::vector<double> distortion = cam["distortion"];
    const std::vector<double> rvec = cam["camera_from_field"]["rvec"];
    const std::vector<double> tvec = cam["camera_from_field"]["tvec"];
    const std::vector<double> centre = cam["center_in_field_m"];
    const std::vector<double> field_t = cam["field_from_camera"]["tvec"];
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(centre[i], field_t[i], 1e-9);
    for (const auto& object : truth["objects"]) {
      const auto& view = object["views"][c];
      EXPECT_EQ(view["camera"], c);
      if (view["center_px"].is_null()) continue;
      const std::vector<double> p = object["position_m"];
      std::vector<cv::Point2d> projected;
      cv::projectPoints(std::vector<cv::Point3d>{{p[0], p[1], p[2]}}, rvec, tvec, k, distortion,
                        projected);
      EXPECT_NEAR(projected[0].x, view["center_px"][0].get<double>(), 1e-6);
      EXPECT_NEAR(projected[0].y, view["center_px"][1].get<double>(), 1e-6);
      EXPECT_EQ(view["visible"].get<bool>(),
                view["in_image"].get<bool>() && view["visible_fraction"].get<double>() >= 0.5);
      hidden_by_net += view["hidden_by_net"].get<bool>();
      if (view["hidden_by_net"].get<bool>()) {
        EXPECT_LE(view["visible_fraction"].get<double>(), 0.5);
        EXPECT_LE(p[0] * centre[0], 0.0) << "hidden by the net from a camera on its side";
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(hidden_by_net, 0);
  const auto boards = nlohmann::json::parse(read_file(dir.path() / "chessboards.json"));
  EXPECT_EQ(boards["cameras"][0]["views"][0]["corners_px"].size(), 54u);
}

TEST(CourtDataset, ACourtWithoutANetSaysSo) {
  const TempDir dir;
  auto options = small_dataset(5);
  options.chessboard_views = 0;
  options.court.net.enabled = false;
  write_court_dataset(options, dir.path());
  const auto truth = nlohmann::json::parse(read_file(dir.path() / "court_0000.json"));
  EXPECT_TRUE(truth["court"]["net"].is_null());
  for (const auto& object : truth["objects"]) {
    for (const auto& view : object["views"]) EXPECT_FALSE(view["hidden_by_net"].get<bool>());
  }
}

TEST(CourtDataset, SameSeedSameBytesDifferentSeedDifferentScene) {
  const TempDir dir;
  const auto files = write_court_dataset(small_dataset(21), dir / "a");
  write_court_dataset(small_dataset(21), dir / "b");
  write_court_dataset(small_dataset(22), dir / "c");
  for (const auto& f : files) {
    EXPECT_EQ(read_file(dir / "a" / f), read_file(dir / "b" / f)) << f;
    EXPECT_NE(read_file(dir / "a" / f), read_file(dir / "c" / f)) << f;
  }
}

TEST(CourtDataset, InvalidOptionsAreNamed) {
  const TempDir temp;
  const fs::path dir = temp / "out";
  auto options = small_dataset(1);
  options.scenes = -1;
  EXPECT_THROW(write_court_dataset(options, dir), InputError);
  options = small_dataset(1);
  options.chessboard_views = 100;
  EXPECT_THROW(write_court_dataset(options, dir), InputError);
  options = small_dataset(1);
  options.rig.height = 0;
  EXPECT_THROW(write_court_dataset(options, dir), InputError);
  EXPECT_FALSE(fs::exists(dir)) << "nothing written on bad options";
}

}  // namespace
}  // namespace ballsight::sim
