#include "ballsight/camera/camera_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>

#include "ballsight/core/error.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

CameraCalibration sample_calibration(std::mt19937_64& rng, bool with_pose, bool rational) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  CameraCalibration c;
  c.intrinsics.width = 1280;
  c.intrinsics.height = 720;
  c.intrinsics.fx = 800.0 + 20.0 * u(rng);
  c.intrinsics.fy = c.intrinsics.fx * (1.0 + 0.003 * u(rng));
  c.intrinsics.cx = 640.0 + 6.0 * u(rng);
  c.intrinsics.cy = 360.0 + 4.0 * u(rng);
  c.intrinsics.distortion = {
      -0.3 + 0.05 * u(rng), 0.1 + 0.02 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng), 0.0, 0.0, 0.0, 0.0};
  if (rational) c.intrinsics.distortion[5] = 0.01 * u(rng);
  c.avg_reprojection_error_px = 0.2 + 0.1 * u(rng);
  if (with_pose) {
    CameraExtrinsics e;
    e.camera_from_field = Rigid3::from_rvec_tvec(Vec3(u(rng), u(rng), u(rng)) * 2.0,
                                                 Vec3(u(rng), u(rng), 20.0 + u(rng)));
    e.reprojection_error_px = 0.1 + 0.05 * u(rng);
    e.reference_count = 6;
    c.extrinsics = e;
  }
  return c;
}

void expect_same(const CameraCalibration& a, const CameraCalibration& b) {
  EXPECT_EQ(a.intrinsics.width, b.intrinsics.width);
  EXPECT_EQ(a.intrinsics.height, b.intrinsics.height);
  EXPECT_DOUBLE_EQ(a.intrinsics.fx, b.intrinsics.fx);
  EXPECT_DOUBLE_EQ(a.intrinsics.fy, b.intrinsics.fy);
  EXPECT_DOUBLE_EQ(a.intrinsics.cx, b.intrinsics.cx);
  EXPECT_DOUBLE_EQ(a.intrinsics.cy, b.intrinsics.cy);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_DOUBLE_EQ(a.intrinsics.distortion[i], b.intrinsics.distortion[i]) << "coefficient " << i;
  }
  ASSERT_EQ(a.avg_reprojection_error_px.has_value(), b.avg_reprojection_error_px.has_value());
  if (a.avg_reprojection_error_px) {
    EXPECT_DOUBLE_EQ(*a.avg_reprojection_error_px, *b.avg_reprojection_error_px);
  }
  ASSERT_EQ(a.extrinsics.has_value(), b.extrinsics.has_value());
  if (!a.extrinsics) return;
  const Rigid3& ta = a.extrinsics->camera_from_field;
  const Rigid3& tb = b.extrinsics->camera_from_field;
  EXPECT_LT((ta.rotation - tb.rotation).norm(), 1e-12);
  EXPECT_LT((ta.translation - tb.translation).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(a.extrinsics->reprojection_error_px, b.extrinsics->reprojection_error_px);
  EXPECT_EQ(a.extrinsics->reference_count, b.extrinsics->reference_count);
}

TEST(CameraFile, RoundTripsThroughTheFile) {
  test::TempDir dir;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const CameraCalibration c = sample_calibration(rng, seed % 2 == 0, seed % 3 == 0);
    const auto path = dir / "cam.yml";
    write_camera_file(path, c);
    expect_same(c, read_camera_file(path));
  }
}

TEST(CameraFile, UsesOpenCVKeyNamesAndOpenCVCanReadIt) {
  std::mt19937_64 rng(3);
  const CameraCalibration c = sample_calibration(rng, true, false);
  const std::string text = camera_file_text(c);
  for (const char* key : {"image_width", "image_height", "camera_matrix", "distortion_coefficients",
                          "avg_reprojection_error", "rvec", "tvec", "extrinsics_reprojection_error",
                          "extrinsics_reference_count"}) {
    EXPECT_NE(text.find(std::string(key) + ":"), std::string::npos) << key;
  }
  cv::FileStorage fs(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  cv::Mat k, d;
  fs["camera_matrix"] >> k;
  fs["distortion_coefficients"] >> d;
  EXPECT_DOUBLE_EQ(k.at<double>(0, 0), c.intrinsics.fx);
  EXPECT_EQ(d.total(), 5u);
  EXPECT_DOUBLE_EQ(d.at<double>(0), c.intrinsics.distortion[0]);
}

TEST(CameraFile, ReadsOpenCVsOwnCalibrationSample) {
  const std::filesystem::path sample =
      "/usr/share/doc/opencv-doc/examples/data/left_intrinsics.yml";
  if (!std::filesystem::exists(sample)) BALLSIGHT_SKIP() << sample << " absent (Debian opencv-doc)";
  const CameraCalibration c = read_camera_file(sample);
  EXPECT_EQ(c.intrinsics.width, 640);
  EXPECT_EQ(c.intrinsics.height, 480);
  EXPECT_NEAR(c.intrinsics.fx, 535.9157, 1e-3);
  EXPECT_NEAR(c.intrinsics.cy, 235.5708, 1e-3);
  EXPECT_NEAR(c.intrinsics.distortion[4], 0.238392, 1e-6);
  ASSERT_TRUE(c.avg_reprojection_error_px.has_value());
  EXPECT_NEAR(*c.avg_reprojection_error_px, 0.392591, 1e-6);
  EXPECT_FALSE(c.extrinsics.has_value());
}

constexpr const char* kRosCameraInfo = R"(image_width: 640
image_height: 480
camera_name: narrow_stereo
camera_matrix:
  rows: 3
  cols: 3
  data: [430.2, 0, 306.7, 0, 430.9, 244.5, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.3362, 0.1197, -0.0009, 0.0003, 0.0]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
projection_matrix:
  rows: 3
  cols: 4
  data: [430.2, 0, 306.7, 0, 0, 430.9, 244.5, 0, 0, 0, 1, 0]
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(CameraFile, ReadsRosCameraInfo) {
  const CameraFile file = parse_camera_file(kRosCameraInfo, "ros.yaml");
  EXPECT_EQ(file.format, CameraFileFormat::ros_camera_info);
  const PinholeParams& p = file.calibration.intrinsics;
  EXPECT_EQ(p.width, 640);
  EXPECT_DOUBLE_EQ(p.fx, 430.2);
  EXPECT_DOUBLE_EQ(p.fy, 430.9);
  EXPECT_DOUBLE_EQ(p.cx, 306.7);
  EXPECT_DOUBLE_EQ(p.cy, 244.5);
  EXPECT_DOUBLE_EQ(p.distortion[0], -0.3362);
  EXPECT_DOUBLE_EQ(p.distortion[2], -0.0009);
  EXPECT_FALSE(file.calibration.avg_reprojection_error_px.has_value());

  std::string rational = kRosCameraInfo;
  rational.replace(rational.find("plumb_bob"), 9, "rational_polynomial");
  rational = replaced(rational, "cols: 5\n  data: [-0.3362, 0.1197, -0.0009, 0.0003, 0.0]",
                      "cols: 8\n  data: [-0.3362, 0.1197, -0.0009, 0.0003, 0.0, 0.01, 0.0, 0.0]");
  EXPECT_DOUBLE_EQ(parse_camera_file(rational, "ros.yaml").calibration.intrinsics.distortion[5],
                   0.01);
}

TEST(CameraFile, OpenCVFormatIsDetected) {
  std::mt19937_64 rng(5);
  EXPECT_EQ(parse_camera_file(camera_file_text(sample_calibration(rng, false, false)), "a").format,
            CameraFileFormat::opencv);
}

// Every bad input names the file and the key.
void expect_error(const std::string& text, const std::string& expected) {
  try {
    parse_camera_file(text, "cam0.yml");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("cam0.yml:", 0), 0u) << e.what();
  }
}

TEST(CameraFile, BadFilesNameTheFileAndTheKey) {
  const std::string ros = kRosCameraInfo;
  expect_error(replaced(ros, "image_width: 640\n", ""), "key 'image_width' missing");
  expect_error(replaced(ros, "image_height: 480", "image_height: tall"),
               "key 'image_height' expected an integer");
  expect_error(replaced(ros, "cols: 3\n  data: [430.2, 0, 306.7, 0, 430.9, 244.5, 0, 0, 1]",
                        "cols: 3\n  data: [430.2, 0, 306.7]"),
               "key 'camera_matrix' has 3 values for 3x3");
  expect_error(replaced(ros, "plumb_bob", "equidistant"),
               "key 'distortion_model' expected plumb_bob or rational_polynomial");
  expect_error(replaced(ros, "cols: 5", "cols: 4"), "key 'distortion_coefficients' has 5 values");
  expect_error(replaced(ros, "430.2, 0, 306.7", "-430.2, 0, 306.7"),
               "key 'camera_matrix' focal lengths must be positive");
  expect_error("image_width: 640\nimage_height: [1, 2\n  camera_matrix: {", "cam0.yml:3:");
  expect_error("- 1\n- 2\n", "cam0.yml:1: expected a YAML map");

  std::mt19937_64 rng(9);
  const std::string opencv = camera_file_text(sample_calibration(rng, true, false));
  expect_error(replaced(opencv, "tvec:", "tvec_old:"), "key 'tvec' missing");
  expect_error(replaced(opencv, "camera_matrix:", "camera_matrix: 3\nold_camera_matrix:"),
               "key 'camera_matrix' expected a matrix");
}

// OpenCV 4.6's YAML reader never returns on these texts (found by fuzz/camera_yaml.cpp): camera
// files are read with yaml-cpp. The first is not YAML; the second is, but has no calibration keys.
TEST(CameraFile, TextThatHangsOpenCVsReaderIsRefused) {
  expect_error("%YAML:1.0\n---\n   dt: d\n  ncv-matrix\n   rows: 3\n",
               "cam0.yml:5:8: not valid YAML");
  expect_error(
      "%YAML:1.0\n---\n# baley n\xd5"
      "ames; docs/sils: 3\n   dt: d\n  ncv-matrix\n   ., 0., 640., "
      "\nextrinsics_%YAML:1.0r\n",
      "cam0.yml:4: key 'image_width' missing");
}

TEST(CameraFile, MissingFileIsAnInputErrorNamingIt) {
  test::TempDir dir;
  try {
    read_camera_file(dir / "nope.yml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.yml"), std::string::npos) << e.what();
  }
}

TEST(CameraFile, AFailedWriteLeavesTheOldFile) {
  test::TempDir dir;
  std::mt19937_64 rng(4);
  const CameraCalibration c = sample_calibration(rng, false, false);
  write_camera_file(dir / "cam.yml", c);
  EXPECT_THROW(write_camera_file(dir / "missing_folder" / "cam.yml", c), InputError);
  expect_same(c, read_camera_file(dir / "cam.yml"));
}

}  // namespace
}  // namespace ballsight
