#include "ballsight/camera/unified.hpp"

#include <gtest/gtest.h>

#include <opencv2/ccalib/omnidir.hpp>

#include "test_cameras.hpp"

namespace ballsight {
namespace {

using test::mirror_camera;

class UnifiedRoundTrip : public ::testing::TestWithParam<double> {};

TEST_P(UnifiedRoundTrip, PixelRayPixelOverDenseGrid) {
  const UnifiedCamera camera(mirror_camera(GetParam()));
  int checked = 0;
  for (double y = 0.0; y < 480.0; y += 1.7) {
    for (double x = 0.0; x < 640.0; x += 1.7) {
      const auto ray = camera.unproject({x, y});
      if (!ray) continue;  // outside the model's image
      EXPECT_NEAR(ray->norm(), 1.0, 1e-12);
      const auto back = camera.project(*ray * 2.5);
      ASSERT_TRUE(back) << "pixel " << x << "," << y;
      ASSERT_NEAR((*back - Vec2(x, y)).norm(), 0.0, 1e-6) << "pixel " << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50000);
}

INSTANTIATE_TEST_SUITE_P(Xi, UnifiedRoundTrip, ::testing::Values(0.0, 0.5, 0.9, 1.0));

TEST(Unified, ProjectsLikeOpenCVOmnidir) {
  const UnifiedParams p = mirror_camera(0.8);
  const UnifiedCamera camera(p);
  std::vector<cv::Point3d> points;
  for (double x = -2.0; x <= 2.0; x += 0.5)
    for (double y = -2.0; y <= 2.0; y += 0.5) points.emplace_back(x, y, 0.7);
  const cv::Matx33d k(p.fx, 0, p.cx, 0, p.fy, p.cy, 0, 0, 1);
  const cv::Matx14d d(p.k1, p.k2, p.p1, p.p2);
  std::vector<cv::Point2d> expected;
  cv::omnidir::projectPoints(points, expected, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), k, p.xi, d);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto pixel = camera.project({points[i].x, points[i].y, points[i].z});
    ASSERT_TRUE(pixel);
    EXPECT_NEAR(pixel->x(), expected[i].x, 1e-6);
    EXPECT_NEAR(pixel->y(), expected[i].y, 1e-6);
  }
}

TEST(Unified, SeesBehindTheImagePlaneWhenXiIsPositive) {
  const UnifiedCamera camera(mirror_camera(0.9));
  // A point slightly behind the camera's plane is still imaged by a catadioptric camera.
  EXPECT_TRUE(camera.project({1.0, 0.0, -0.2}));
  EXPECT_FALSE(camera.project({0.0, 0.0, -1.0}));
}

}  // namespace
}  // namespace ballsight
