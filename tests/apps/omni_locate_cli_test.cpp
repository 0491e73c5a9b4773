#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "apps/run_cli.hpp"
#include "ballsight/camera/ground_map_io.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace fs = std::filesystem;

// A misaligned rig's true mapping as a table, and a frame of a ball it sees.
class OmniLocateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    sim::OmniScene scene;
    scene.rig.tilt_deg = 1.5;
    scene.rig.center_offset_px = {4.0, -3.0};
    scene.robot_pose = {{3.0, 4.0}, rad_from_deg(30.0)};
    scene.ball = sim::OmniBall{{4.0, 6.0}};
    scene.effects.noise_sigma = 3.0;
    const OmniRig rig(scene.rig);
    GroundMapInfo info;
    info.min_radius_px = 50.0;
    info.max_radius_px = 230.0;
    save_ground_map(lut, ground_map_from_rig(rig, info));
    write_png_atomic(image, sim::render_omni_scene(scene).bgr);
  }

  TempDir dir;
  fs::path lut = dir / "truth.bsgm";
  fs::path image = dir / "frame.png";
};

TEST_F(OmniLocateCli, PlacesTheBallOnTheField) {
  const CliResult r = run_cli({"omni", "locate", "--lut", lut.string(), "--image", image.string(),
                               "--robot", "300,400,30", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json out = nlohmann::json::parse(r.stdout_text);
  ASSERT_TRUE(out["found"].get<bool>());
  EXPECT_NEAR(out["ball_in_field_cm"][0].get<double>(), 400.0, 1.0);
  EXPECT_NEAR(out["ball_in_field_cm"][1].get<double>(), 600.0, 1.0);
  const CliResult text = run_cli({"omni", "locate", "--lut", lut.string(), "--image",
                                  image.string(), "--robot", "300,400,30"});
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_EQ(line_count(text.stdout_text), 1) << text.stdout_text;
}

TEST_F(OmniLocateCli, BadInputIsOneLine) {
  const fs::path small = dir / "small.png";
  write_png_atomic(small, cv::Mat(240, 320, CV_8UC3, cv::Scalar(0, 0, 0)));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--image", small.string(), "--robot", "0,0,0"}, "image is 320x240, expected 640x480"},
      {{"--image", image.string(), "--robot", "1,2"}, "--robot"},
      {{"--image", image.string(), "--robot", "0,0,0", "--ball-bgr", "0,300,0"}, "--ball-bgr"},
      {{"--image", (dir / "missing.png").string(), "--robot", "0,0,0"}, "missing.png"}};
  for (const auto& [args, problem] : cases) {
    std::vector<std::string> full = {"omni", "locate", "--lut", lut.string()};
    full.insert(full.end(), args.begin(), args.end());
    const CliResult r = run_cli(full);
    EXPECT_EQ(r.exit_code, 2) << problem;
    EXPECT_EQ(line_count(r.stderr_text), 1) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(problem), std::string::npos) << r.stderr_text;
  }
}

}  // namespace
}  // namespace ballsight::test
