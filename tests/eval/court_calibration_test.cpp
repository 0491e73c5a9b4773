#include "ballsight/eval/court_calibration.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <opencv2/imgcodecs.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

const std::filesystem::path kExampleSite =
    std::filesystem::path(BALLSIGHT_SOURCE_DIR) / "docs" / "examples" / "site.yml";

CameraCalibration true_intrinsics(const sim::CourtCamera& camera) {
  CameraCalibration calibration;
  calibration.intrinsics = camera.camera.params();
  return calibration;
}

double rotation_error_deg(const Rigid3& a, const Rigid3& b) {
  return deg_from_rad(Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle());
}

// The documented example site (the simulator's court and reference balls) and the rendered image
// alone give every camera's pose: within 3 cm and 0.06 degrees (issue 4 asks for a few cm and
// 0.2 degrees).
TEST(CourtCalibration, RenderedViewsGiveEveryCameraItsPose) {
  const Site site = read_site(kExampleSite);
  double worst_position = 0.0, worst_rotation = 0.0, worst_rms = 0.0;
  for (const std::uint64_t seed : {1u, 2u}) {
    const sim::CourtRig rig = sim::make_court_rig({}, {}, seed);
    const sim::CourtScene scene = sim::make_court_scene(rig.court, {}, seed);  // noise, shadow
    for (std::size_t c = 0; c < rig.cameras.size(); ++c) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " camera " + std::to_string(c));
      const sim::CourtCamera& truth = rig.cameras[c];
      const cv::Mat image = sim::CourtRenderer(truth, rig.court).render(scene, seed).bgr;
      const CameraPoseReport report =
          calibrate_site_camera(site, site.cameras[c], image, "view.png", true_intrinsics(truth));
      const double position_error =
          (report.pose.camera_from_field.inverse().translation - truth.center_in_field()).norm();
      const double rotation_error =
          rotation_error_deg(report.pose.camera_from_field, truth.camera_from_field);
      EXPECT_LT(position_error, 0.03);
      EXPECT_LT(rotation_error, 0.06);
      EXPECT_GE(report.pose.matches.size(), 6u);
      EXPECT_LT(report.pose.rms_px, 0.3);
      ASSERT_TRUE(report.calibration.extrinsics.has_value());
      EXPECT_EQ(report.calibration.extrinsics->reference_count,
                static_cast<int>(report.pose.matches.size()));
      worst_position = std::max(worst_position, position_error);
      worst_rotation = std::max(worst_rotation, rotation_error);
      worst_rms = std::max(worst_rms, report.pose.rms_px);
      std::cout << "seed " << seed << " camera " << c << ": " << report.pose.matches.size()
                << " references, rms " << report.pose.rms_px << " px, position error "
                << 100 * position_error << " cm, rotation error " << rotation_error << " deg\n";
    }
  }
  std::cout << "worst: position " << 100 * worst_position << " cm, rotation " << worst_rotation
            << " deg, rms " << worst_rms << " px\n";
}

TEST(CourtCalibration, FewerThanFourReferenceBallsNamesTheMissingOnes) {
  const Site site = read_site(kExampleSite);
  const sim::CourtRig rig = sim::make_court_rig({}, {}, 3);
  sim::CourtScene scene = sim::make_court_scene(rig.court, {}, 3);
  // Camera 0 (north-east) keeps three reference balls near it: singles_ne, service_ne, t_east.
  std::erase_if(scene.balls, [](const sim::SceneSphere& b) {
    return b.kind == sim::ObjectKind::reference_ball && b.id != 0 && b.id != 4 && b.id != 8;
  });
  const cv::Mat image = sim::CourtRenderer(rig.cameras[0], rig.court).render(scene, 3).bgr;
  try {
    calibrate_site_camera(site, site.cameras[0], image, "court_0000_cam0.png",
                          true_intrinsics(rig.cameras[0]));
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("camera 'ne' (court_0000_cam0.png): reference balls: found 3 of 12 "
                        "(singles_ne, service_ne, t_east), at least 4 needed; missing: "
                        "singles_se, singles_sw, singles_nw, service_se, service_sw, service_nw, "
                        "t_west, net_north, net_south"),
              std::string::npos)
        << what;
  }
}

TEST(CourtCalibration, ImageOfTheWrongSizeIsAnInputError) {
  const Site site = read_site(kExampleSite);
  const sim::CourtRig rig = sim::make_court_rig({}, {}, 3);
  const cv::Mat image(360, 640, CV_8UC3, cv::Scalar::all(100));
  try {
    calibrate_site_camera(site, site.cameras[1], image, "small.png",
                          true_intrinsics(rig.cameras[1]));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("camera 'se' (small.png): image is 640x360, its "
                                         "calibration"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("cam1.yml is for 1280x720"), std::string::npos)
        << e.what();
  }
}

TEST(CourtCalibration, AFailingCameraLeavesEveryFileUntouched) {
  test::TempDir dir;
  const sim::CourtRig rig = sim::make_court_rig({}, {}, 1);
  const sim::CourtScene scene = sim::make_court_scene(rig.court, {}, 1);
  for (std::size_t c = 0; c < 4; ++c) {
    const std::string index = std::to_string(c);
    write_camera_file(dir / ("cam" + index + ".yml"), true_intrinsics(rig.cameras[c]));
    cv::Mat image = sim::CourtRenderer(rig.cameras[c], rig.court).render(scene, 1).bgr;
    if (c == 3) image.setTo(cv::Scalar::all(90));  // a camera that sees nothing
    cv::imwrite((dir / ("court_0000_cam" + index + ".png")).string(), image);
  }
  std::filesystem::copy_file(kExampleSite, dir / "site.yml");
  const Site site = read_site(dir / "site.yml");
  const std::string before = camera_file_text(read_camera_file(dir / "cam0.yml"));
  try {
    calibrate_site(site);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("camera 'nw'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("found 0 of 12"), std::string::npos) << e.what();
  }
  EXPECT_EQ(camera_file_text(read_camera_file(dir / "cam0.yml")), before);
  EXPECT_FALSE(read_camera_file(dir / "cam0.yml").extrinsics.has_value());

  // With the fourth camera's view restored every file gets its pose.
  cv::imwrite((dir / "court_0000_cam3.png").string(),
              sim::CourtRenderer(rig.cameras[3], rig.court).render(scene, 1).bgr);
  const std::vector<CameraPoseReport> reports = calibrate_site(site);
  ASSERT_EQ(reports.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c) {
    const CameraCalibration written = read_camera_file(dir / ("cam" + std::to_string(c) + ".yml"));
    ASSERT_TRUE(written.extrinsics.has_value());
    EXPECT_LT((written.extrinsics->camera_from_field.inverse().translation -
               rig.cameras[c].center_in_field())
                  .norm(),
              0.05);
  }
}

TEST(CourtCalibration, SourcesOtherThanStillImages) {
  SiteCamera camera;
  camera.name = "gate";
  camera.source.kind = CameraSource::Kind::url;
  camera.source.url = "rtsp://10.0.0.2/live";
  EXPECT_THROW(first_source_image(camera), InputError);
  test::TempDir dir;
  camera.source = {CameraSource::Kind::folder, dir.path(), 0, {}};
  EXPECT_THROW(first_source_image(camera), InputError);  // empty folder
  cv::imwrite((dir / "b.png").string(), cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(0)));
  cv::imwrite((dir / "a.png").string(), cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(0)));
  std::ofstream(dir / "0_notes.txt") << "not an image";
  EXPECT_EQ(first_source_image(camera), dir / "a.png");
}

}  // namespace
}  // namespace ballsight
