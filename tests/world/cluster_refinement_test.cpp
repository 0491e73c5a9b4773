#include "ballsight/world/cluster_refinement.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

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

// Groups fitted side by side come back in the groups' order however long each takes, every
// group once; a group's failure reaches the caller.
TEST(ClusterRefinement, GroupsFittedSideBySideKeepTheirOrder) {
  std::vector<std::vector<int>> groups;
  for (int g = 0; g < 12; ++g) groups.push_back({g, 100 + g});
  std::atomic<int> calls{0};
  const std::vector<FusedObject> out =
      fit_groups_in_parallel(groups, [&](const std::vector<int>& group) {
        ++calls;  // the early groups take longest: a fit's end says nothing of its place
        std::this_thread::sleep_for(std::chrono::milliseconds(12 - group[0]));
        std::vector<FusedObject> objects(2);
        objects[0].position_m = Vec2(group[0], 0);
        objects[1].position_m = Vec2(group[1], 0);
        return objects;
      });
  EXPECT_EQ(calls, 12);
  ASSERT_EQ(out.size(), 24u);
  for (std::size_t k = 0; k < out.size(); ++k)
    EXPECT_EQ(out[k].position_m.x(), static_cast<double>(k % 2 == 0 ? k / 2 : 100 + k / 2)) << k;
  EXPECT_THROW(fit_groups_in_parallel(groups,
                                      [](const std::vector<int>& group) {
                                        if (group[0] == 5) throw std::runtime_error("group 5");
                                        return std::vector<FusedObject>{};
                                      }),
               std::runtime_error);
}

}  // namespace
}  // namespace ballsight
