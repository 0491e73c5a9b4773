#include "ballsight/world/observation_fusion.hpp"

#include <gtest/gtest.h>

#include <random>

#include "field_cameras.hpp"

namespace ballsight {
namespace {

// The observation camera `c` makes of a ball at `p` declaring `sigma_px` of pixel error; with
// `rng`, an error of two thirds of that is drawn (a detector declares a little more than it makes).
FieldObservation observe(int c, const Vec3& p, double sigma_px, std::mt19937_64* rng = nullptr) {
  const FieldCamera camera = test::corner_cameras()[static_cast<size_t>(c)];
  PixelDetection d;
  d.center_px = *camera.pixel_from_field(p);
  if (rng) {
    std::normal_distribution<double> noise(0.0, 2.0 * sigma_px / 3.0);
    d.center_px += Vec2(noise(*rng), noise(*rng));
  }
  d.center_sigma_px = sigma_px;
  FieldObservation o = *observe_on_plane(camera, d, p.z(), {0.0});
  o.camera = c;
  return o;
}

TEST(ObservationFusion, OneBallSeenByThreeCamerasIsOneBall) {
  const std::uint64_t seed = 3;
  std::mt19937_64 rng(seed);
  const Vec3 ball(2.0, 1.0, 0.0335);
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
    const std::vector<FieldObservation> obs{
        observe(0, ball, 0.15, &rng), observe(1, ball, 0.15, &rng), observe(2, ball, 0.15, &rng)};
    const auto fused = fuse_observations(obs, {});
    ASSERT_EQ(fused.size(), 1u);
    EXPECT_EQ(fused[0].cameras, (std::vector<int>{0, 1, 2}));
    // The information-weighted mean beats every camera's own error bound.
    EXPECT_LT((fused[0].position_m - ball.head<2>()).norm(), 0.03);
  }
}

// Two balls 8 cm apart, each seen by two cameras: two balls, each from its own observations.
TEST(ObservationFusion, BallsEightCentimetresApartStayDistinct) {
  const std::uint64_t seed = 4;
  std::mt19937_64 rng(seed);
  const Vec3 a(1.0, -2.0, 0.0335), b(1.08, -2.0, 0.0335);
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
    const std::vector<FieldObservation> obs{observe(0, a, 0.15, &rng), observe(3, a, 0.15, &rng),
                                            observe(0, b, 0.15, &rng), observe(3, b, 0.15, &rng)};
    const auto fused = fuse_observations(obs, {});
    ASSERT_EQ(fused.size(), 2u);
    for (const FusedObject& f : fused) {
      EXPECT_EQ(f.cameras, (std::vector<int>{0, 3}));
      const double to_a = (f.position_m - a.head<2>()).norm(),
                   to_b = (f.position_m - b.head<2>()).norm();
      EXPECT_LT(std::min(to_a, to_b), 0.03);
    }
  }
}

// A camera sees a ball once: two of its observations never merge, however close.
TEST(ObservationFusion, OneCameraNeverMergesWithItself) {
  const Vec3 a(0.0, 0.0, 0.0335);
  const auto fused =
      fuse_observations({observe(1, a, 0.3), observe(1, a + Vec3(0.01, 0, 0), 0.3)}, {});
  EXPECT_EQ(fused.size(), 2u);
}

// The gate is the expected error: 15 cm apart along the line of sight is the same ball for two
// imprecise observations and two balls for precise ones.
TEST(ObservationFusion, GateFollowsTheExpectedError) {
  const Vec3 ball(-3.0, 2.0, 0.0335);
  const Vec2 sight =
      (ball.head<2>() - test::corner_cameras()[1].center_in_field().head<2>()).normalized();
  const Vec3 offset(0.15 * sight.x(), 0.15 * sight.y(), 0.0);
  EXPECT_EQ(fuse_observations({observe(0, ball, 1.5), observe(1, ball + offset, 1.5)}, {}).size(),
            1u);
  EXPECT_EQ(fuse_observations({observe(0, ball, 0.05), observe(1, ball + offset, 0.05)}, {}).size(),
            2u);
}

}  // namespace
}  // namespace ballsight
