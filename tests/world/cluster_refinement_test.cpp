#include "ballsight/world/cluster_refinement.hpp"

#include <gtest/gtest.h>

#include "field_cameras.hpp"

namespace ballsight {
namespace {

constexpr double kBallRadius = 0.0335;

// Camera c's observation of the mean image of `balls` (one blob when they touch in its view).
FieldObservation blob_of(int c, const std::vector<Vec3>& balls, int split = 1) {
  const FieldCamera camera = test::corner_cameras()[static_cast<size_t>(c)];
  PixelDetection d;
  for (const Vec3& b : balls)
    d.center_px += *camera.pixel_from_field(b) / static_cast<double>(balls.size());
  d.center_sigma_px = 0.1;
  d.split_count = split;
  d.blob_objects = static_cast<double>(balls.size() * static_cast<size_t>(split));
  FieldObservation o = *observe_on_plane(camera, d, kBallRadius, {0.05});
  o.camera = c;
  return o;
}

// Two touching balls: camera 0 sees two blobs, cameras 1 and 2 one merged blob each. Pairwise
// fusion leaves the merged blobs on one ball; the refit lets each cover both and places both balls.
TEST(ClusterRefinement, AMergedBlobCoversBothTouchingBalls) {
  const Vec3 a(2.0, 1.0, kBallRadius), b(2.069, 1.0, kBallRadius);
  const std::vector<FieldObservation> obs{blob_of(0, {a}), blob_of(0, {b}), blob_of(1, {a, b}),
                                          blob_of(2, {a, b})};
  const auto fused = fuse_observations(obs, {});
  const auto refined = refine_clusters(obs, fused, kBallRadius, {});
  ASSERT_EQ(refined.size(), 2u);
  for (const FusedObject& ball : refined) {
    const double error =
        std::min((ball.position_m - a.head<2>()).norm(), (ball.position_m - b.head<2>()).norm());
    EXPECT_LT(error, 0.01);
    EXPECT_EQ(ball.cameras, (std::vector<int>{0, 1, 2}));
  }
}

// One ball whose observations were fused into two groups (a wrongly split blob) becomes one.
TEST(ClusterRefinement, NeedlessBallsAreRemoved) {
  const Vec3 a(-4.0, 2.0, kBallRadius);
  std::vector<FieldObservation> obs{blob_of(0, {a}), blob_of(1, {a}), blob_of(2, {a}),
                                    blob_of(3, {a})};
  FusedObject first, second;
  first.position_m = a.head<2>() + Vec2(0.03, 0.0);
  first.observations = {0, 1};
  first.cameras = {0, 1};
  second.position_m = a.head<2>() - Vec2(0.03, 0.0);
  second.observations = {2, 3};
  second.cameras = {2, 3};
  const auto refined = refine_clusters(obs, {first, second}, kBallRadius, {});
  ASSERT_EQ(refined.size(), 1u);
  EXPECT_LT((refined[0].position_m - a.head<2>()).norm(), 0.005);
  EXPECT_EQ(refined[0].cameras, (std::vector<int>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace ballsight
