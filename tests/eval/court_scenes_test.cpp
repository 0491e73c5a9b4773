// ballsight's world model on single scenes of `eval court`, rendered again on their own.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ballsight/detect/court_detector.hpp"
#include "ballsight/eval/court_eval_calibration.hpp"
#include "ballsight/eval/court_eval_scenes.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/world/court_world.hpp"

namespace ballsight {
namespace {

// The rig's true cameras (no calibration) and the court detector's findings in each.
struct Seen {
  std::vector<FieldCamera> cameras;
  std::vector<std::optional<std::vector<PixelDetection>>> detections;
};

Seen seen_by_the_rig(const CourtEvalScenes& scenes, const RenderedCourtScene& rendered) {
  Seen seen;
  for (size_t k = 0; k < rendered.renders.size(); ++k) {
    const sim::CourtCamera& camera = scenes.rig().cameras[k];
    seen.cameras.push_back({camera.camera, camera.camera_from_field});
    seen.detections.emplace_back(
        CourtDetector(seen.cameras.back()).detect(rendered.renders[k].bgr));
  }
  return seen;
}

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
    const Seen seen = seen_by_the_rig(scenes, rendered);
    const WorldModel model = build_world_model(seen.cameras, seen.detections, {});
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

// Two touching balls beside the robot (scene 8 of seed 1 under warm lamps, as `eval court
// --light indoor` renders it): one camera sees both, split; the robot's body hides one of them
// from the other cameras. The pixel fit leaves out the pixels where the body stands in front of
// the balls' plane; before, it read them as "no ball there" and merged the pair into one (the
// nearest estimate to the hidden one was 7.8 cm off).
TEST(CourtScenes, ABallTheRobotHidesFromAllButOneCameraIsKept) {
  sim::CourtRigOptions rig;
  rig.width = sim::kReportCameraWidth;
  rig.height = sim::kReportCameraHeight;
  const CourtEvalScenes scenes({}, rig, 1);
  sim::CourtScenarioOptions indoor;
  indoor.light = sim::LightCondition::indoor;
  const RenderedCourtScene rendered = scenes.render(indoor, 8);
  const Seen seen = seen_by_the_rig(scenes, rendered);
  // The world model as `eval court` sets it up (the net among what hides balls).
  const CourtWorldOptions options = ballsight_options_for_site(simulated_site(scenes.rig())).world;
  const WorldModel model = build_world_model(seen.cameras, seen.detections, options);
  ASSERT_TRUE(model.robot);
  const Vec2 hidden(-0.771, -1.746);  // the pair's hidden ball, to the millimetre
  int checked = 0;
  for (const sim::SceneSphere& sphere : rendered.scene.balls) {
    const Vec2 truth = sphere.center_in_field.head<2>();
    if (sphere.kind != sim::ObjectKind::tennis_ball || (truth - hidden).norm() > 0.1) continue;
    double nearest = 1e9;
    for (const FusedBall& ball : model.balls)
      nearest = std::min(nearest, (ball.position_m - truth).norm());
    EXPECT_LT(nearest, 0.02) << "ball at " << truth.transpose();
    ++checked;
  }
  EXPECT_EQ(checked, 2);  // the pair
}

}  // namespace
}  // namespace ballsight
