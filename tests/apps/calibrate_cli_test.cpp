#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "apps/run_cli.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/core/file_io.hpp"
#include "example_site.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

namespace fs = std::filesystem;

const fs::path kOpenCVSamples = "/usr/share/doc/opencv-doc/examples/data";
using test::kExampleSite;

TEST(CalibrateCameraCli, OpenCVsSamplePhotos) {
  if (!fs::exists(kOpenCVSamples / "left01.jpg")) {
    BALLSIGHT_SKIP() << kOpenCVSamples
                     << " absent: install Debian's opencv-doc (scripts/setup does)";
  }
  const TempDir temp;
  const CliResult r =
      run_cli({"calibrate", "camera", "--images", (kOpenCVSamples / "left??.jpg").string(),
               "--board", "9x6", "--square", "0.025", "--out", (temp / "left.yml").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  // One line per photo, then the summary.
  EXPECT_NE(r.stdout_text.find("left01.jpg: 0."), std::string::npos) << r.stdout_text;
  EXPECT_NE(r.stdout_text.find("calibrated from 13 of 13 images (640x480)"), std::string::npos)
      << r.stdout_text;
  const CameraCalibration c = read_camera_file(temp / "left.yml");
  ASSERT_TRUE(c.avg_reprojection_error_px.has_value());
  EXPECT_LE(*c.avg_reprojection_error_px, 0.45);
  EXPECT_NEAR(c.intrinsics.fx, 535.9, 0.01 * 535.9);  // OpenCV's own result: left_intrinsics.yml
  std::cout << r.stdout_text;

  // left*.jpg also matches left.jpg, a 612x459 photo of another camera.
  expect_one_line_error(
      run_cli({"calibrate", "camera", "--images", (kOpenCVSamples / "left*.jpg").string(),
               "--board", "9x6", "--square", "0.025", "--out", (temp / "all.yml").string()}),
      "left01.jpg: image is 640x480, the first image (" + (kOpenCVSamples / "left.jpg").string() +
          ") is 612x459: every view must come from one camera");
}

TEST(CalibrateCameraCli, BadInputsFailWithOneLine) {
  const TempDir temp;
  const std::string out = (temp / "cam.yml").string();
  const auto calibrate = [&](const std::string& images, const std::string& board) {
    return run_cli({"calibrate", "camera", "--images", images, "--board", board, "--square", "0.05",
                    "--out", out});
  };
  expect_one_line_error(calibrate((temp / "*.png").string(), "9x6"), "no file matches");
  expect_one_line_error(calibrate((temp / "*.png").string(), "9-6"),
                        "--board: expected inner corners as COLSxROWS");
  expect_one_line_error(calibrate((temp / "*.png").string(), "6x6"), "must differ");
  expect_one_line_error(run_cli({"calibrate", "camera", "--images", (temp / "*.png").string(),
                                 "--square", "0", "--out", out}),
                        "square: must be a positive length");
  for (int i = 0; i < 3; ++i) {
    cv::imwrite((temp / ("blank" + std::to_string(i) + ".png")).string(),
                cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(128)));
  }
  expect_one_line_error(calibrate((temp / "blank*.png").string(), "9x6"),
                        "the 9x6 board was not found in any of the 3 image(s)");
  cv::imwrite((temp / "blank3.png").string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(128)));
  expect_one_line_error(calibrate((temp / "blank*.png").string(), "9x6"),
                        "blank3.png: image is 640x480, the first image");
  write_file_atomic(temp / "broken.png", "not a png");
  expect_one_line_error(calibrate((temp / "broken.png").string(), "9x6"),
                        "broken.png: not a readable image");
  EXPECT_FALSE(fs::exists(out)) << "nothing written on error";
}

// The whole set-up on simulated data: chessboards -> intrinsics per camera, the documented
// example site -> every camera's pose, checked against the simulator's truth.
TEST(CourtCalibrateCli, SimulatedCourtEndToEnd) {
  const TempDir temp;
  const fs::path dir = temp / "sim";
  const CliResult sim =
      run_cli({"sim", "court", "--out", dir.string(), "--seed", "1", "--chessboards", "12"});
  ASSERT_EQ(sim.exit_code, 0) << sim.stderr_text;
  for (int c = 0; c < 4; ++c) {
    const std::string cam = "cam" + std::to_string(c);
    const CliResult r =
        run_cli({"calibrate", "camera", "--images", (dir / (cam + "_board_*.png")).string(),
                 "--board", "9x6", "--square", "0.05", "--out", (dir / (cam + ".yml")).string()});
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  }
  fs::copy_file(kExampleSite, dir / "site.yml");
  const CliResult r = run_cli({"court", "calibrate", "--site", (dir / "site.yml").string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  std::cout << r.stdout_text;
  const nlohmann::json truth = nlohmann::json::parse(read_file(dir / "court_0000.json"));
  for (int c = 0; c < 4; ++c) {
    SCOPED_TRACE("camera " + std::to_string(c));
    const CameraCalibration calibration =
        read_camera_file(dir / ("cam" + std::to_string(c) + ".yml"));
    ASSERT_TRUE(calibration.extrinsics.has_value());
    const auto& center = truth["cameras"][c]["center_in_field_m"];
    const Vec3 true_center(center[0].get<double>(), center[1].get<double>(),
                           center[2].get<double>());
    const Vec3 found = calibration.extrinsics->camera_from_field.inverse().translation;
    Mat3 true_rotation;
    for (int i = 0; i < 9; ++i) {
      true_rotation(i / 3, i % 3) =
          truth["cameras"][c]["camera_from_field"]["rotation"][i / 3][i % 3].get<double>();
    }
    const double rotation_error_deg =
        Eigen::AngleAxisd(calibration.extrinsics->camera_from_field.rotation.transpose() *
                          true_rotation)
            .angle() *
        180.0 / M_PI;
    const double fx_error = calibration.intrinsics.fx / truth["cameras"][c]["fx"].get<double>() - 1;
    EXPECT_LT((found - true_center).norm(), 0.05) << found.transpose();
    EXPECT_LT(rotation_error_deg, 0.2);
    EXPECT_LT(std::abs(fx_error), 0.005);
    std::cout << "camera " << c << ": fx error " << 100 * fx_error << "%, position error "
              << 100 * (found - true_center).norm() << " cm, rotation error " << rotation_error_deg
              << " deg\n";
    EXPECT_GE(calibration.extrinsics->reference_count, 6);
    EXPECT_LT(calibration.extrinsics->reprojection_error_px, 0.3);
    EXPECT_TRUE(calibration.avg_reprojection_error_px.has_value()) << "intrinsics kept";
  }
}

TEST(CourtCalibrateCli, BadSitesFailWithOneLine) {
  const TempDir temp;
  expect_one_line_error(run_cli({"court", "calibrate", "--site", (temp / "none.yml").string()}),
                        "none.yml");
  std::string site = read_file(kExampleSite);
  write_file_atomic(temp / "site.yml", site + "colour:\n  ball: [1, 2, 3]\n");
  expect_one_line_error(run_cli({"court", "calibrate", "--site", (temp / "site.yml").string()}),
                        "site.yml:65: unknown key 'colour'");
  expect_one_line_error(
      run_cli({"court", "calibrate", "--site", (temp / "site.yml").string(), "--attempts", "0"}),
      "attempts");
  expect_one_line_error(
      run_cli({"court", "calibrate", "--site", (temp / "site.yml").string(), "--retry-wait", "-1"}),
      "--retry-wait");
}

// Every camera is tried: each failure is one line naming the camera, then one error line says
// which failed and that nothing was written.
TEST(CourtCalibrateCli, FailingCamerasAreEachReported) {
  const TempDir temp;
  std::string site = read_file(kExampleSite);
  const std::string ne = "{file: court_0000_cam0.png}";
  site.replace(site.find(ne), ne.size(), "{device: 97}");
  write_file_atomic(temp / "site.yml", site);
  CameraCalibration calibration;
  calibration.intrinsics.width = 1280;
  calibration.intrinsics.height = 720;
  calibration.intrinsics.fx = calibration.intrinsics.fy = 800;
  calibration.intrinsics.cx = 639.5;
  calibration.intrinsics.cy = 359.5;
  for (const char* cam : {"cam0.yml", "cam2.yml", "cam3.yml"}) {
    write_camera_file(temp / cam, calibration);
  }
  cv::imwrite((temp / "court_0000_cam3.png").string(),
              cv::Mat(720, 1280, CV_8UC3, cv::Scalar::all(128)));
  const CliResult r = run_cli({"court", "calibrate", "--site", (temp / "site.yml").string(),
                               "--attempts", "2", "--retry-wait", "0"});
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_EQ(r.stdout_text, "");
  for (const std::string& line : std::vector<std::string>{
           "ballsight: camera 'ne': cannot open video device 97 (gave up after 2 attempts)\n",
           "ballsight: camera 'se': " + (temp / "cam1.yml").string() +
               ": cannot open for reading\n",
           "ballsight: camera 'sw': " + (temp / "court_0000_cam2.png").string() +
               ": cannot open for reading\n",
           "ballsight: camera 'nw' (file " + (temp / "court_0000_cam3.png").string() +
               "): reference balls: found 0 of 12",
           "ballsight: error: 4 of 4 cameras failed (ne, se, sw, nw); no calibration file "
           "written\n"}) {
    EXPECT_NE(r.stderr_text.find(line), std::string::npos) << line << "\n" << r.stderr_text;
  }
  EXPECT_FALSE(read_camera_file(temp / "cam3.yml").extrinsics.has_value());
}

}  // namespace
}  // namespace ballsight::test
