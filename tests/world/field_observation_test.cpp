#include "ballsight/world/field_observation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "field_cameras.hpp"

namespace ballsight {
namespace {

PixelDetection detection_of(const FieldCamera& camera, const Vec3& p, double sigma_px = 0.1) {
  PixelDetection d;
  d.center_px = *camera.pixel_from_field(p);
  d.center_sigma_px = sigma_px;
  return d;
}

// Pixel -> plane at the object's centre height -> pixel: the point comes back, for balls on the
// floor and markers 34.5 cm up, anywhere on the court.
TEST(FieldObservation, RoundTripOnThePlaneOfTheCentre) {
  const std::uint64_t seed = 5;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(-15.0, 15.0), y(-7.0, 7.0);
  for (const FieldCamera& camera : test::corner_cameras()) {
    for (int i = 0; i < 50; ++i) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " sample " + std::to_string(i));
      for (double height : {0.0335, 0.345}) {
        const Vec3 p(x(rng), y(rng), height);
        const auto o = observe_on_plane(camera, detection_of(camera, p), height, {});
        ASSERT_TRUE(o.has_value());
        EXPECT_LT((o->position_m - p.head<2>()).norm(), 1e-6);
        EXPECT_NEAR(o->range_m, (p - camera.center_in_field()).norm(), 1e-6);
      }
    }
  }
}

// Intersecting with the floor instead (the report's z = 0) puts a ball's centre behind it by
// radius x distance / camera height.
TEST(FieldObservation, TheFloorIsTheWrongPlane) {
  const FieldCamera camera = test::corner_cameras()[0];
  const Vec3 ball(0.0, 0.0, 0.0335);
  const auto on_floor = observe_on_plane(camera, detection_of(camera, ball), 0.0, {});
  const double horizontal = (ball.head<2>() - camera.center_in_field().head<2>()).norm();
  const double expected = 0.0335 * horizontal / (5.0 - 0.0335);
  EXPECT_NEAR((on_floor->position_m - ball.head<2>()).norm(), expected, 1e-3);
}

// The expected error grows with distance and is stretched along the line of sight (the ray
// grazes the plane): the gate depends on where the ball is, not a fixed guess.
TEST(FieldObservation, ExpectedErrorFollowsDistanceAndViewingDirection) {
  const FieldCamera camera = test::corner_cameras()[0];
  const Vec3 near(12.0, 6.0, 0.0335), far(-10.0, -3.0, 0.0335);
  const auto o_near = observe_on_plane(camera, detection_of(camera, near), 0.0335, {});
  const auto o_far = observe_on_plane(camera, detection_of(camera, far), 0.0335, {});
  EXPECT_GT(o_far->covariance_m2.trace(), 4.0 * o_near->covariance_m2.trace());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> shape(o_far->covariance_m2);
  const Vec2 major = shape.eigenvectors().col(1);
  const Vec2 sight = (far.head<2>() - camera.center_in_field().head<2>()).normalized();
  EXPECT_GT(std::abs(major.dot(sight)), 0.99);
  EXPECT_GT(shape.eigenvalues()(1), 9.0 * shape.eigenvalues()(0));
  // A pixel's offset maps to the plane through the Jacobian (to 3% over a whole pixel).
  PixelDetection shifted;
  shifted.center_px = *camera.pixel_from_field(far) + Vec2(0.0, 1.0);
  const auto o_moved = observe_on_plane(camera, shifted, 0.0335, {});
  const Vec2 predicted = o_far->plane_per_pixel * Vec2(0.0, 1.0);
  const Vec2 actual = o_moved->position_m - o_far->position_m;
  EXPECT_LT((predicted - actual).norm(), 0.03 * actual.norm());
}

TEST(FieldObservation, MahalanobisDistanceScalesWithTheErrors) {
  const Eigen::Matrix2d small = 1e-4 * Eigen::Matrix2d::Identity();
  EXPECT_NEAR(mahalanobis_squared(Vec2(0, 0), small, Vec2(0.02, 0), small), 2.0, 1e-9);
  EXPECT_NEAR(mahalanobis_squared(Vec2(0, 0), 4 * small, Vec2(0.02, 0), 4 * small), 0.5, 1e-9);
}

}  // namespace
}  // namespace ballsight
