#include "ballsight/pipeline/court_calibration.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "example_site.hpp"
#include "http_file_server.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using test::kExampleSite;

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

// On a red or a wooden court the simulator's reference balls are violet; the site names their
// colour and every camera is posed as on a green court (orange ones are lost in those floors:
// `eval court --surface red` found 3 of 12 with them).
TEST(CourtCalibration, VioletReferenceBallsPoseTheCamerasOnRedAndWoodenCourts) {
  for (const sim::CourtSurface surface : {sim::CourtSurface::red, sim::CourtSurface::wood}) {
    sim::TennisCourtSpec court;
    sim::set_court_surface(court, surface);
    ASSERT_EQ(court.reference_ball_bgr, sim::kVioletBgr);
    const sim::CourtRig rig = sim::make_court_rig(court, {}, 1);
    const sim::CourtScene scene = sim::make_court_scene(rig.court, {}, 1);
    Site violet_site = read_site(kExampleSite);
    violet_site.colours.reference_ball = Rgb::from_bgr(sim::kVioletBgr);
    for (std::size_t c = 0; c < rig.cameras.size(); ++c) {
      SCOPED_TRACE(std::string(sim::court_surface_name(surface)) + " camera " + std::to_string(c));
      const sim::CourtCamera& truth = rig.cameras[c];
      const cv::Mat image = sim::CourtRenderer(truth, rig.court).render(scene, 1).bgr;
      const CameraPoseReport report = calibrate_site_camera(
          violet_site, violet_site.cameras[c], image, "view.png", true_intrinsics(truth));
      EXPECT_GE(report.pose.matches.size(), 6u);
      EXPECT_LT(report.pose.rms_px, 0.3);
      EXPECT_LT(
          (report.pose.camera_from_field.inverse().translation - truth.center_in_field()).norm(),
          0.03);
      EXPECT_LT(rotation_error_deg(report.pose.camera_from_field, truth.camera_from_field), 0.06);
    }
  }
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

// Camera files with the true intrinsics, the example site and its file sources (rendered views;
// camera `blind` sees nothing).
sim::CourtRig write_site(const test::TempDir& dir, int blind = -1) {
  const sim::CourtRig rig = sim::make_court_rig({}, {}, 1);
  const sim::CourtScene scene = sim::make_court_scene(rig.court, {}, 1);
  for (std::size_t c = 0; c < 4; ++c) {
    const std::string index = std::to_string(c);
    write_camera_file(dir / ("cam" + index + ".yml"), true_intrinsics(rig.cameras[c]));
    cv::Mat image = sim::CourtRenderer(rig.cameras[c], rig.court).render(scene, 1).bgr;
    if (static_cast<int>(c) == blind) image.setTo(cv::Scalar::all(90));
    cv::imwrite((dir / ("court_0000_cam" + index + ".png")).string(), image);
  }
  std::filesystem::copy_file(kExampleSite, dir / "site.yml");
  return rig;
}

void expect_poses_written(const test::TempDir& dir, const sim::CourtRig& rig) {
  for (std::size_t c = 0; c < 4; ++c) {
    const CameraCalibration written = read_camera_file(dir / ("cam" + std::to_string(c) + ".yml"));
    ASSERT_TRUE(written.extrinsics.has_value());
    EXPECT_LT((written.extrinsics->camera_from_field.inverse().translation -
               rig.cameras[c].center_in_field())
                  .norm(),
              0.05);
  }
}

// Every camera is tried and the failures say which; no file is touched unless all succeeded.
TEST(CourtCalibration, AFailingCameraLeavesEveryFileUntouched) {
  test::TempDir dir;
  const sim::CourtRig rig = write_site(dir, 3);
  const Site site = read_site(dir / "site.yml");
  const std::string before = camera_file_text(read_camera_file(dir / "cam0.yml"));
  const SiteCalibration failed = calibrate_site(site);
  EXPECT_FALSE(failed.written);
  EXPECT_EQ(failed.calibrated.size(), 3u);
  ASSERT_EQ(failed.failed.size(), 1u);
  EXPECT_EQ(failed.failed[0].camera, "nw");
  EXPECT_EQ(
      failed.failed[0].error.rfind("camera 'nw' (file " + (dir / "court_0000_cam3.png").string() +
                                       "): reference balls: found 0 of 12",
                                   0),
      0u)
      << failed.failed[0].error;
  EXPECT_EQ(camera_file_text(read_camera_file(dir / "cam0.yml")), before);
  EXPECT_FALSE(read_camera_file(dir / "cam0.yml").extrinsics.has_value());

  // With the fourth camera's view restored every file gets its pose.
  cv::imwrite((dir / "court_0000_cam3.png").string(),
              sim::CourtRenderer(rig.cameras[3], rig.court)
                  .render(sim::make_court_scene(rig.court, {}, 1), 1)
                  .bgr);
  const SiteCalibration done = calibrate_site(site);
  EXPECT_TRUE(done.written);
  EXPECT_TRUE(done.failed.empty());
  ASSERT_EQ(done.calibrated.size(), 4u);
  expect_poses_written(dir, rig);
}

// A short video of a camera's view, as a file. FFV1 (lossless): OpenCV's MJPG at its default
// quality leaves 2 of the 12 reference balls of camera ne's view (1-2 px balls lose their colour).
std::filesystem::path write_video(const test::TempDir& dir, const std::string& name) {
  const cv::Mat view = cv::imread((dir / (name + ".png")).string());
  const std::filesystem::path video = dir / (name + ".avi");
  cv::VideoWriter writer(video.string(), cv::VideoWriter::fourcc('F', 'F', 'V', '1'), 5,
                         view.size());
  EXPECT_TRUE(writer.isOpened()) << "OpenCV cannot write FFV1 .avi here";
  for (int k = 0; k < 3; ++k) writer.write(view);
  return video;
}

void replace_source(const std::filesystem::path& site_file, const std::string& from,
                    const std::string& to) {
  std::string text = read_file(site_file);
  text.replace(text.find(from), from.size(), to);
  write_file_atomic(site_file, text);
}

// URL sources are read through the same FrameSource as `court run`'s: camera ne's view streamed
// over HTTP from 127.0.0.1 as a video, camera nw's URL refused; the other cameras are calibrated,
// nw's failure names the camera and the source, nothing is written until nw streams too.
TEST(CourtCalibration, UrlSourcesAreStreamedAndAClosedOneIsReported) {
  test::TempDir dir;
  const sim::CourtRig rig = write_site(dir);
  test::HttpFileServer ne_stream(write_video(dir, "court_0000_cam0"));
  const std::string refused =
      "http://127.0.0.1:" + std::to_string(test::closed_loopback_port()) + "/live";
  replace_source(dir / "site.yml", "{file: court_0000_cam0.png}",
                 "{url: " + ne_stream.url("ne.avi") + "}");
  replace_source(dir / "site.yml", "{file: court_0000_cam3.png}", "{url: " + refused + "}");
  CourtCalibrationOptions options;
  options.frame.attempts = 2;
  options.frame.backoff = {std::chrono::milliseconds(1), std::chrono::milliseconds(1), 1.0};
  options.frame.live_frames = 3;

  const SiteCalibration failed = calibrate_site(read_site(dir / "site.yml"), options);
  EXPECT_FALSE(failed.written);
  ASSERT_EQ(failed.failed.size(), 1u);
  EXPECT_EQ(failed.failed[0].camera, "nw");
  EXPECT_EQ(failed.failed[0].error,
            "camera 'nw': cannot open " + refused + " (gave up after 2 attempts)");
  ASSERT_EQ(failed.calibrated.size(), 3u);
  const CameraPoseReport& ne = failed.calibrated[0];
  EXPECT_EQ(ne.camera, "ne");
  EXPECT_EQ(ne.source, ne_stream.url("ne.avi"));
  EXPECT_GE(ne.pose.matches.size(), 6u);
  EXPECT_LT(
      (ne.pose.camera_from_field.inverse().translation - rig.cameras[0].center_in_field()).norm(),
      0.05);
  std::cout << "ne from an HTTP stream: " << ne.pose.matches.size() << " references, rms "
            << ne.pose.rms_px << " px, position error "
            << 100 * (ne.pose.camera_from_field.inverse().translation -
                      rig.cameras[0].center_in_field())
                         .norm()
            << " cm\n";
  EXPECT_FALSE(read_camera_file(dir / "cam0.yml").extrinsics.has_value());

  test::HttpFileServer nw_stream(write_video(dir, "court_0000_cam3"));
  replace_source(dir / "site.yml", refused, nw_stream.url("nw.avi"));
  const SiteCalibration done = calibrate_site(read_site(dir / "site.yml"), options);
  EXPECT_TRUE(done.failed.empty()) << done.failed[0].error;
  EXPECT_TRUE(done.written);
  expect_poses_written(dir, rig);
}

}  // namespace
}  // namespace ballsight
