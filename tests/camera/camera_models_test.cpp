// Properties every camera model holds, run for each model (a typed test): a pixel's ray projects
// back to the pixel, over the image and along its border, and a point behind the camera has no
// pixel. The unified model's Jacobian is checked on its template (unified_model_test.cpp).

#include <gtest/gtest.h>

#include "test_cameras.hpp"

namespace ballsight {
namespace {

template <class Camera>
Camera make_camera();

template <>
PinholeCamera make_camera<PinholeCamera>() {
  return PinholeCamera(test::wide_hd_camera());
}

template <>
UnifiedCamera make_camera<UnifiedCamera>() {
  return UnifiedCamera(test::mirror_camera(0.8));
}

template <class Camera>
class CameraModel : public ::testing::Test {};

using Models = ::testing::Types<PinholeCamera, UnifiedCamera>;
TYPED_TEST_SUITE(CameraModel, Models);

// Whether `pixel` unprojects to a unit ray that projects back to it; `refused` when it does not
// unproject at all (outside the model's image).
::testing::AssertionResult round_trip(const auto& camera, const Vec2& pixel, bool& refused) {
  const std::optional<Vec3> ray = camera.unproject(pixel);
  refused = !ray;
  if (refused) return ::testing::AssertionSuccess();
  if (std::abs(ray->norm() - 1.0) > 1e-9)
    return ::testing::AssertionFailure() << "ray of norm " << ray->norm();
  const std::optional<Vec2> back = camera.project(3.7 * *ray);
  if (!back) return ::testing::AssertionFailure() << "its ray does not project";
  if ((*back - pixel).norm() > 1e-6)
    return ::testing::AssertionFailure() << "projects to " << back->transpose();
  return ::testing::AssertionSuccess();
}

TYPED_TEST(CameraModel, UnprojectThenProjectIsThePixel) {
  const TypeParam camera = make_camera<TypeParam>();
  int used = 0, all = 0;
  for (double y = 0.0; y < camera.height(); y += 3.1)
    for (double x = 0.0; x < camera.width(); x += 3.1) {
      bool refused = false;
      EXPECT_TRUE(round_trip(camera, Vec2(x, y), refused)) << "pixel " << x << ", " << y;
      used += refused ? 0 : 1;
      ++all;
    }
  EXPECT_GT(used, all * 9 / 10);
}

// Along the image's outer edge (pixel centres from -0.5 to size - 0.5): a pixel is either
// imaged correctly or refused, never given a wrong ray.
TYPED_TEST(CameraModel, BorderPixelsRoundTripOrAreRefused) {
  const TypeParam camera = make_camera<TypeParam>();
  const double right = camera.width() - 0.5, bottom = camera.height() - 0.5;
  std::vector<Vec2> border;
  for (double x = -0.5; x <= right; x += 1.0) {
    border.emplace_back(x, -0.5);
    border.emplace_back(x, bottom);
  }
  for (double y = -0.5; y <= bottom; y += 1.0) {
    border.emplace_back(-0.5, y);
    border.emplace_back(right, y);
  }
  for (const Vec2& pixel : border) {
    bool refused = false;
    EXPECT_TRUE(round_trip(camera, pixel, refused)) << "pixel " << pixel.transpose();
  }
}

TYPED_TEST(CameraModel, APointBehindTheCameraHasNoPixel) {
  const TypeParam camera = make_camera<TypeParam>();
  EXPECT_FALSE(camera.project(Vec3(0.0, 0.0, -1.0)));
  EXPECT_FALSE(camera.project(Vec3(0.1, -0.2, -3.0)));
  EXPECT_FALSE(camera.project(Vec3::Zero()));
}

}  // namespace
}  // namespace ballsight
