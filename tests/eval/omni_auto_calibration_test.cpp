#include "ballsight/eval/omni_auto_calibration.hpp"

#include <gtest/gtest.h>

#include "ballsight/calib/ballsight_model.hpp"
#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/simulated_calibration.hpp"
#include "ballsight/sim/omni_marker_layout.hpp"
#include "ballsight/sim/omni_renderer.hpp"

namespace ballsight {
namespace {

TEST(OmniAutoCalibration, CalibratesAMisalignedRigFromOneRenderedFrame) {
  sim::OmniScene scene;
  scene.rig.tilt_deg = 1.5;
  scene.rig.tilt_azimuth_deg = 200.0;
  scene.rig.center_offset_px = {5.0, -3.0};
  scene.robot_pose = {{4.0, 6.0}, 0.7};
  scene.markers = sim::calibration_markers(scene.robot_pose);
  scene.effects.noise_sigma = 3.0;
  scene.noise_seed = 11;
  const cv::Mat frame = sim::render_omni_scene(scene).bgr;

  std::vector<Vec2> layout;
  for (const sim::FloorMarker& m : sim::calibration_markers(Pose2D{}))
    layout.push_back(m.position_in_field);
  const Vec2 center(319.5, 239.5);
  const MarkerFrameSamples found =
      samples_from_marker_frame(frame, layout, scene.palette.marker_bgr, center);
  EXPECT_GE(found.samples.size(), layout.size() * 95 / 100) << found.blobs << " blobs";

  // Every matched sample carries its marker's true distance, so a wrong match shows as a large
  // distance error of the fitted model on its own samples; the held-out error shows the rest.
  const OmniRig rig(scene.rig);
  const BallsightGroundModel model = fit_ballsight_model(found.samples, {640, 480, center});
  EXPECT_LT(sample_errors(model, found.samples).distance_cm.max, 10.0);
  const GroundErrors held_out = ground_errors(model, random_floor_truth(rig, 60.0, 460.0, 2000, 5));
  // Measured: median 0.92 cm, p95 1.13 cm (seed above). A binary blob centroid of a flat disc
  // seen obliquely is not the projection of its centre, a bias every sample shares; clicked
  // markers (1 px noise, no bias) give a median of about 0.3 cm.
  EXPECT_LT(held_out.position_cm.median, 1.2);
  EXPECT_LT(held_out.position_cm.p95, 2.0);
}

}  // namespace
}  // namespace ballsight
