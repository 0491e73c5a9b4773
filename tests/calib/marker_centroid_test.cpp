#include "ballsight/calib/marker_centroid.hpp"

#include <gtest/gtest.h>

#include "ballsight/sim/omni_scenario.hpp"
#include "ballsight/sim/omni_truth.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

// The predicted shift of each disc's image centroid agrees with the simulator's analytic
// outline centroid (the referee) for the paper's layout on a misaligned rig, the model fitted to
// exact clicks.
TEST(MarkerCentroid, PredictsTheSimulatorsOutlineCentroidShift) {
  const OmniRig rig(test::paper_misaligned_rig());
  SimulatedCalibrationOptions clicks = test::paper_markers(3);
  clicks.click_noise_px = 0.0;
  const BallsightGroundModel model =
      fit_ballsight_model(simulate_calibration(rig, clicks).samples, {});

  sim::OmniScene scene;
  scene.rig = test::paper_misaligned_rig();
  scene.markers = sim::calibration_markers(scene.robot_pose);
  double largest_shift_px = 0.0;
  for (const sim::OmniMarkerTruth& m : sim::make_omni_truth(scene, rig).markers) {
    ASSERT_TRUE(m.pixel && m.silhouette_centroid_px);
    const std::optional<Vec2> offset =
        disc_centroid_offset_px(model.params(), 100.0 * m.position_in_robot, 100.0 * m.radius_m);
    ASSERT_TRUE(offset);
    const Vec2 truth = *m.silhouette_centroid_px - *m.pixel;
    EXPECT_LT((*offset - truth).norm(), 0.01) << "marker " << m.id;
    largest_shift_px = std::max(largest_shift_px, truth.norm());
  }
  EXPECT_GT(largest_shift_px, 0.1);  // the shift is real, not zero on both sides
}

// Centroids at the predicted shifts come back to the discs' centres.
TEST(MarkerCentroid, DiscCentresUndoTheShift) {
  const CatadioptricFloorParams params;
  const FoundDisc disc{Vec2::Zero(), {1.5, 0.8}, 0.05};
  const Vec2 offset = *disc_centroid_offset_px(params, 100.0 * disc.p_in_robot, 5.0);
  const FoundDisc shifted{Vec2(300.0, 200.0) + offset, disc.p_in_robot, disc.radius_m};
  const std::vector<MarkerObservation> centres = disc_centres({&shifted, 1}, params);
  ASSERT_EQ(centres.size(), 1u);
  EXPECT_LT((centres[0].pixel - Vec2(300.0, 200.0)).norm(), 1e-12);
  EXPECT_EQ(centres[0].p_in_robot, disc.p_in_robot);
}

}  // namespace
}  // namespace ballsight
