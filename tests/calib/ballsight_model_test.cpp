#include "ballsight/calib/ballsight_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/polynomial_model.hpp"
#include "ballsight/core/angle.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

struct Fitted {
  OmniRig rig;
  SimulatedCalibration calibration;
  BallsightGroundModel model;
};

Fitted fit_simulated(const SimulatedCalibrationOptions& markers, double tilt_azimuth_deg = 30.0,
                     const BallsightFitOptions& options = {}) {
  OmniRig rig(test::paper_misaligned_rig(tilt_azimuth_deg));
  SimulatedCalibration calibration = simulate_calibration(rig, markers);
  BallsightGroundModel model = fit_ballsight_model(calibration.samples, {}, options);
  return {std::move(rig), std::move(calibration), std::move(model)};
}

GroundErrors held_out(const Fitted& fitted, std::uint64_t seed) {
  return ground_errors(fitted.model, random_floor_truth(fitted.rig, 60.0, 460.0, 2000, seed));
}

// The paper's set-up: a 1.5 deg tilt and a 5 px centre offset, markers clicked with 1 px noise.
// ballsight's model maps ground points to ~0.5 cm (median); the paper's polynomial to ~24 cm.
TEST(BallsightModel, HeldOutErrorOnTheMisalignedRigIsFarBelowThePolynomial) {
  for (const double azimuth : {0.0, 130.0, 250.0}) {
    const std::uint64_t seed = 40 + static_cast<std::uint64_t>(azimuth);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", tilt azimuth " + std::to_string(azimuth));
    const Fitted fitted = fit_simulated(test::paper_markers(seed), azimuth);
    const GroundErrors errors = held_out(fitted, seed + 1);
    EXPECT_LT(errors.position_cm.median, 1.0);
    EXPECT_LT(errors.position_cm.p95, 3.0);
    EXPECT_EQ(errors.out_of_range, 0u);
    EXPECT_EQ(errors.unmapped, 0u);
    const PolynomialGroundModel poly = fit_polynomial_model(fitted.calibration.samples, {});
    EXPECT_GT(ground_errors(poly, random_floor_truth(fitted.rig, 60.0, 460.0, 2000, seed + 1))
                  .position_cm.median,
              10.0 * errors.position_cm.median);
  }
}

// The fitted physics is the rig's: tilt angle and principal point come back.
TEST(BallsightModel, RecoversTheMisalignment) {
  const Fitted fitted = fit_simulated(test::paper_markers(7));
  const CatadioptricFloorParams& p = fitted.model.params();
  EXPECT_NEAR(deg_from_rad(p.rotation_rad.head<2>().norm()), 1.5, 0.3);
  EXPECT_NEAR((p.principal_px - fitted.rig.principal_point()).norm(), 0.0, 1.0);
}

// Property: the distance increases strictly along every one of 360 rays over the valid range.
// The model family holds the rig: exact clicks give back its parameters, the viewpoint height
// included (which noisy floor clicks determine only to a few cm).
TEST(BallsightModel, ExactClicksRecoverTheRigsParameters) {
  SimulatedCalibrationOptions markers = test::paper_markers(8);
  markers.click_noise_px = 0.0;
  const Fitted fitted = fit_simulated(markers);
  const CatadioptricFloorParams& p = fitted.model.params();
  const OmniRigParams truth = test::paper_misaligned_rig();
  EXPECT_NEAR(p.xi, truth.xi, 1e-3);
  EXPECT_NEAR(p.focal_px, truth.focal_px, 0.05);
  EXPECT_NEAR(p.height_cm, 100.0 * truth.height_m, 0.02);
}

// A measured viewpoint height is weighed by its standard deviation: a tight measurement holds
// the fitted height, a loose one lets the markers speak.
TEST(BallsightModel, MeasuredViewpointHeightIsAPrior) {
  const double truth_cm = 100.0 * test::paper_misaligned_rig().height_m;
  BallsightFitOptions options;
  options.viewpoint_height_cm = truth_cm + 3.0;
  options.viewpoint_height_sigma_cm = 0.01;
  EXPECT_NEAR(fit_simulated(test::paper_markers(9), 30.0, options).model.params().height_cm,
              truth_cm + 3.0, 0.05);
  SimulatedCalibrationOptions exact = test::paper_markers(9);
  exact.click_noise_px = 0.0;
  options.viewpoint_height_sigma_cm = 100.0;
  EXPECT_NEAR(fit_simulated(exact, 30.0, options).model.params().height_cm, truth_cm, 0.1);
}

TEST(BallsightModel, StrictlyMonotoneAlongEveryRay) {
  for (const std::uint64_t seed : {3u, 4u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Fitted fitted = fit_simulated(test::paper_markers(seed));
    const RadiusRange range = fitted.model.domain().valid_radius;
    EXPECT_LT(range.min_px, 82.0);   // the 60 cm ring, around 81 px
    EXPECT_GT(range.max_px, 205.0);  // the 460 cm ring
    for (int ray = 0; ray < 360; ++ray) {
      const double theta = ray + 0.5;
      double previous = -INFINITY;
      for (double r = range.min_px; r <= range.max_px; r += 0.1) {
        const GroundPrediction p = fitted.model.predict(theta, r);
        ASSERT_TRUE(p.in_range) << theta << " deg, " << r << " px";
        ASSERT_GT(p.distance_cm, previous) << theta << " deg, " << r << " px";
        previous = p.distance_cm;
      }
    }
  }
}

TEST(BallsightModel, FlagsQueriesOutsideItsRange) {
  const Fitted fitted = fit_simulated(test::paper_markers(8));
  const RadiusRange range = fitted.model.domain().valid_radius;
  EXPECT_TRUE(fitted.model.predict(45.0, 0.5 * (range.min_px + range.max_px)).in_range);
  EXPECT_FALSE(fitted.model.predict(45.0, range.min_px - 1.0).in_range);
  EXPECT_FALSE(fitted.model.predict(45.0, range.max_px + 1.0).in_range);
  const GroundPrediction beyond_horizon = fitted.model.predict(45.0, 300.0);
  EXPECT_FALSE(beyond_horizon.in_range);
  EXPECT_TRUE(std::isnan(beyond_horizon.distance_cm));
  const Vec2 center = fitted.model.domain().image.center_px;
  EXPECT_FALSE(fitted.model.robot_point_cm(center + Vec2(range.max_px + 2.0, 0.0)));
  EXPECT_TRUE(fitted.model.robot_point_cm(center + Vec2(range.max_px - 2.0, 0.0)));
}

// Five markers labelled with the next ring's distance (50 cm off) barely change the fit: its
// held-out errors stay near those of the same clicks labelled right.
TEST(BallsightModel, RobustToFiveMislabelledSamples) {
  for (const std::uint64_t seed : {11u, 12u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    SimulatedCalibrationOptions markers = test::paper_markers(seed);
    const GroundErrors clean = held_out(fit_simulated(markers), seed + 100);
    markers.mislabelled = 5;
    const Fitted fitted = fit_simulated(markers);
    ASSERT_EQ(fitted.calibration.mislabelled.size(), 5u);
    const GroundErrors errors = held_out(fitted, seed + 100);
    EXPECT_LT(errors.position_cm.median, 1.0);
    EXPECT_LT(errors.position_cm.median, 1.2 * clean.position_cm.median);
    EXPECT_LT(errors.position_cm.p95, 1.2 * clean.position_cm.p95);
  }
}

// Samples with distance only (as the paper's CSV) still fit, and the model still corrects the
// bearing for the tilt and centre offset.
TEST(BallsightModel, DistanceOnlySamplesStillMapDirection) {
  SimulatedCalibrationOptions markers = test::paper_markers(13);
  markers.with_bearing = false;
  const Fitted fitted = fit_simulated(markers);
  const GroundErrors errors = held_out(fitted, 14);
  EXPECT_LT(errors.distance_cm.median, 1.0);
  EXPECT_LT(errors.position_cm.median, 1.5);
  EXPECT_TRUE(fitted.model.predict(10.0, 150.0).bearing_deg);
}

TEST(BallsightModel, Fits400Samples) {
  SimulatedCalibrationOptions markers = test::paper_markers(15);
  markers.rings = 10;
  markers.rays = 40;
  const Fitted fitted = fit_simulated(markers);
  EXPECT_EQ(fitted.calibration.samples.size(), 400u);
  EXPECT_LT(held_out(fitted, 16).position_cm.median, 1.0);
}

TEST(BallsightModel, RejectsTooFewSamples) {
  std::vector<PolarSample> samples;
  for (int i = 0; i < 10; ++i) samples.push_back({36.0 * i, 80.0 + i, i < 5 ? 60.0 : 110.0, {}});
  EXPECT_NE(test::input_error([&] {
              fit_ballsight_model(samples, {});
            }).find("at least 8 samples at 3 distinct distances, got 10 at 2"),
            std::string::npos);
}

TEST(BallsightModel, RejectsANonPositiveMeasuredHeight) {
  BallsightFitOptions options;
  options.viewpoint_height_cm = -60.0;
  EXPECT_NE(test::input_error([&] { options.validate(); }).find("viewpoint_height_cm"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
