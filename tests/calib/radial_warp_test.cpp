#include "ballsight/calib/radial_warp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>

#include "ballsight/core/angle.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

double smooth_shift(double theta_deg, double radius_px) {
  return 2.0 + std::sin(rad_from_deg(theta_deg)) * (radius_px - 100.0) / 50.0;
}

std::vector<WarpTarget> dense_targets(std::uint64_t seed, double noise_px) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> theta(0.0, 360.0), radius(60.0, 200.0);
  std::normal_distribution<double> noise(0.0, noise_px);
  std::vector<WarpTarget> targets;
  for (int i = 0; i < 600; ++i) {
    const double t = theta(rng), r = radius(rng);
    targets.push_back({t, r, smooth_shift(t, r) + noise(rng)});
  }
  return targets;
}

// Within the penalty's bias at the default smoothing (about 3 % at the peaks).
TEST(RadialWarp, RecoversASmoothShift) {
  RadialWarpFitOptions options;
  options.theta_segments = 16;
  const RadialWarp warp = fit_radial_warp(dense_targets(1, 0.0), options);
  for (double t = 0.0; t < 360.0; t += 7.0) {
    for (double r = 65.0; r <= 195.0; r += 13.0) {
      EXPECT_NEAR(warp(t, r), smooth_shift(t, r), 0.15) << t << " deg, " << r << " px";
    }
  }
}

// Beyond its radius span the shift stays at the span's end value: the physical model alone
// decides how the mapping goes on, and monotonicity is kept.
TEST(RadialWarp, IsConstantBeyondItsSpan) {
  const RadialWarp warp = fit_radial_warp(dense_targets(2, 0.0));
  for (double t = 0.0; t < 360.0; t += 30.0) {
    EXPECT_DOUBLE_EQ(warp(t, 10.0), warp(t, 1.0));
    EXPECT_DOUBLE_EQ(warp(t, 400.0), warp(t, 1000.0));
  }
}

TEST(RadialWarp, PeriodicInTheImageAngle) {
  const RadialWarp warp = fit_radial_warp(dense_targets(3, 0.3));
  for (double r = 70.0; r < 200.0; r += 10.0) {
    EXPECT_NEAR(warp(0.0, r), warp(360.0, r), 1e-12);
    EXPECT_NEAR(warp(-10.0, r), warp(350.0, r), 1e-12);
    EXPECT_NEAR(warp(359.999, r), warp(0.0, r), 1e-3);
  }
}

// 5 % of the targets 30 px off (mislabelled rings) barely move the fit (Huber loss).
TEST(RadialWarp, RobustToAFewWildTargets) {
  std::vector<WarpTarget> targets = dense_targets(4, 0.3);
  for (std::size_t i = 0; i < targets.size(); i += 20) targets[i].shift_px += 30.0;
  RadialWarpFitOptions options;
  options.theta_segments = 16;
  const RadialWarp warp = fit_radial_warp(targets, options);
  for (double t = 0.0; t < 360.0; t += 20.0) {
    for (double r = 70.0; r <= 190.0; r += 20.0) EXPECT_NEAR(warp(t, r), smooth_shift(t, r), 0.6);
  }
}

TEST(RadialWarp, JsonRoundTripsExactly) {
  const RadialWarp warp = fit_radial_warp(dense_targets(5, 0.3));
  const RadialWarp back = RadialWarp::from_json(warp.to_json(), "warp");
  for (double t = 0.0; t < 360.0; t += 11.0) {
    for (double r = 50.0; r <= 210.0; r += 9.0) EXPECT_EQ(back(t, r), warp(t, r));
  }
}

TEST(RadialWarp, BadJsonNamesTheField) {
  nlohmann::json value = fit_radial_warp(dense_targets(6, 0.0)).to_json();
  value["coefficients"].erase(0);
  EXPECT_NE(
      test::input_error([&] { RadialWarp::from_json(value, "warp"); }).find("warp.coefficients"),
      std::string::npos);
  value = fit_radial_warp(dense_targets(6, 0.0)).to_json();
  value["radius_span_px"] = {100.0, 50.0};
  EXPECT_NE(
      test::input_error([&] { RadialWarp::from_json(value, "warp"); }).find("warp.radius_span_px"),
      std::string::npos);
  EXPECT_NE(test::input_error([] { fit_radial_warp({}); }).find("warp targets"), std::string::npos);
  std::vector<WarpTarget> targets = dense_targets(6, 0.0);
  targets[3].shift_px = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(test::input_error([&] { fit_radial_warp(targets); }).find("expected finite"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
