#include "ballsight/camera/pinhole.hpp"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>

#include "ballsight/core/error.hpp"
#include "test_cameras.hpp"

namespace ballsight {
namespace {

using test::wide_hd_camera;

TEST(Pinhole, PixelRayPixelRoundTripOverDenseGrid) {
  const PinholeCamera camera(wide_hd_camera());
  int checked = 0;
  for (double y = 0.0; y < 720.0; y += 3.3) {
    for (double x = 0.0; x < 1280.0; x += 3.3) {
      const auto ray = camera.unproject({x, y});
      ASSERT_TRUE(ray) << "pixel " << x << "," << y;
      EXPECT_NEAR(ray->norm(), 1.0, 1e-12);
      const auto back = camera.project(*ray);
      ASSERT_TRUE(back);
      ASSERT_NEAR((*back - Vec2(x, y)).norm(), 0.0, 1e-6) << "pixel " << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 80000);
}

TEST(Pinhole, ProjectsLikeOpenCV) {
  const PinholeCamera camera(wide_hd_camera());
  std::vector<cv::Point3d> points;
  for (double x = -2.0; x <= 2.0; x += 0.25)
    for (double y = -1.0; y <= 1.0; y += 0.25) points.emplace_back(x, y, 3.0);
  std::vector<cv::Point2d> expected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera.camera_matrix(),
                    camera.distortion_coefficients(), expected);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto pixel = camera.project({points[i].x, points[i].y, points[i].z});
    ASSERT_TRUE(pixel);
    EXPECT_NEAR(pixel->x(), expected[i].x, 1e-9);
    EXPECT_NEAR(pixel->y(), expected[i].y, 1e-9);
  }
}

TEST(Pinhole, RejectsPointsBehindAndBeyondTheFold) {
  const PinholeCamera camera(wide_hd_camera());
  EXPECT_FALSE(camera.project({0.0, 0.0, -1.0}));
  // Far outside the invertible region of a strongly barrel-distorted lens.
  EXPECT_FALSE(camera.project({20.0, 0.0, 1.0}));
}

TEST(Pinhole, RoundTripsThroughOpenCVMatrices) {
  const PinholeCamera camera(wide_hd_camera());
  const PinholeCamera copy = PinholeCamera::from_opencv(
      camera.camera_matrix(), camera.distortion_coefficients(), cv::Size(1280, 720));
  EXPECT_EQ(copy.params().distortion, camera.params().distortion);
  EXPECT_DOUBLE_EQ(copy.params().fy, 905.0);
}

TEST(Pinhole, InvalidParametersAreNamed) {
  PinholeParams p = wide_hd_camera();
  p.fx = -1.0;
  EXPECT_THROW(PinholeCamera{p}, InputError);
  p = wide_hd_camera();
  p.width = 0;
  EXPECT_THROW(PinholeCamera{p}, InputError);
  EXPECT_THROW(PinholeCamera::from_opencv(cv::Matx33d::eye(), cv::Mat::zeros(1, 3, CV_64F),
                                          cv::Size(10, 10)),
               InputError);
}

}  // namespace
}  // namespace ballsight
