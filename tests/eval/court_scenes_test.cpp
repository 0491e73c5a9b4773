// ballsight's world model on single scenes of `eval court`, rendered again on their own.

#include <gtest/gtest.h>

#include <string>

#include "ballsight/detect/court_detector.hpp"
#include "ballsight/eval/court_eval_scenes.hpp"
#include "ballsight/world/court_world.hpp"

namespace ballsight {
namespace {

// Scenes of `eval court` where ballsight's pixel fit of clusters (world/pixel_cluster_fit.hpp)
// went wrong: a refit group's blobs reached into another group's and each fitted the shared blob
// apart, both placing a ball in one spot; a ball added to a cluster moved its neighbours so that
// another was no longer needed; a far ball that one camera alone sees was split in two along its
// line of sight (scene 3 of seed 3). Rendered (each camera's noise seeded as the evaluation does)
// and seen through the rig's true cameras (no calibration), no ball is the nearest of two
// estimates. Scenes 16 and 3 of seed 3 and 5 of seed 7 failed so before the fix; scene 14 of
// seed 2 showed its duplicate only through the evaluation's calibrated cameras and is kept as a
// case.
TEST(CourtScenes, NoBallHasTwoEstimates) {
  struct Case {
    std::uint64_t seed;
    int scene;
  };
  for (const Case& c : {Case{2, 14}, Case{3, 16}, Case{7, 5}, Case{3, 3}}) {
    SCOPED_TRACE("eval court --seed " + std::to_string(c.seed) + ", scene " +
                 std::to_string(c.scene));
    const CourtEvalScenes scenes({}, {}, c.seed);
    const RenderedCourtScene rendered = scenes.render({}, c.scene);
    const sim::CourtScene& scene = rendered.scene;
    std::vector<FieldCamera> cameras;
    std::vector<std::optional<std::vector<PixelDetection>>> detections;
    for (size_t k = 0; k < rendered.renders.size(); ++k) {
      const sim::CourtCamera& camera = scenes.rig().cameras[k];
      cameras.push_back({camera.camera, camera.camera_from_field});
      detections.emplace_back(CourtDetector(cameras.back()).detect(rendered.renders[k].bgr));
    }
    const WorldModel model = build_world_model(cameras, detections, {});
    std::vector<Vec2> truth;
    for (const sim::SceneSphere& sphere : scene.balls)
      if (sphere.kind == sim::ObjectKind::tennis_ball)
        truth.push_back(sphere.center_in_field.head<2>());
    // No two estimates of one ball: each estimate's nearest true ball is its own.
    std::vector<int> estimates_of(truth.size(), 0);
    for (const FusedBall& ball : model.balls) {
      size_t nearest = 0;
      for (size_t t = 1; t < truth.size(); ++t)
        if ((truth[t] - ball.position_m).norm() < (truth[nearest] - ball.position_m).norm())
          nearest = t;
      ++estimates_of[nearest];
    }
    for (size_t t = 0; t < truth.size(); ++t)
      EXPECT_LE(estimates_of[t], 1) << "ball at " << truth[t].transpose();
  }
}

}  // namespace
}  // namespace ballsight
