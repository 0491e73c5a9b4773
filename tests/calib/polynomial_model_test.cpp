#include "ballsight/calib/polynomial_model.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/conventions.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

// d(r) = sum c_k r^k sampled without noise is recovered exactly, for several degrees.
TEST(PolynomialModel, ReproducesAKnownPolynomial) {
  const std::vector<std::vector<double>> truths = {
      {5.0, 0.9},                                      // degree 1
      {-20.0, 1.5, -2e-3, 3e-5},                       // degree 3
      {100.0, -2.0, 0.03, -2e-4, 7e-7, -1e-9, 6e-13},  // degree 6
  };
  for (const auto& c : truths) {
    const int degree = static_cast<int>(c.size()) - 1;
    SCOPED_TRACE("degree " + std::to_string(degree));
    const auto truth = [&](double r) {
      double value = 0.0;
      for (auto it = c.rbegin(); it != c.rend(); ++it) value = value * r + *it;
      return value;
    };
    std::vector<PolarSample> samples;
    for (double r = 70.0; r <= 210.0; r += 7.0) samples.push_back({r, r, truth(r), {}});
    const PolynomialGroundModel model = fit_polynomial_model(samples, {}, {degree});
    ASSERT_EQ(model.polynomial().coefficients.size(), c.size());
    for (double r = 70.0; r <= 210.0; r += 0.37) {
      EXPECT_NEAR(model.predict(12.0, r).distance_cm, truth(r), 1e-9 * std::abs(truth(r)) + 1e-9)
          << r;
    }
  }
}

TEST(PolynomialModel, DirectionIsTheImageDirectionAndRangeIsFlagged) {
  std::vector<PolarSample> samples;
  for (double r = 80.0; r <= 200.0; r += 10.0) samples.push_back({0.0, r, 2.0 * r, {}});
  const PolynomialGroundModel model = fit_polynomial_model(samples, {}, {2});
  const GroundPrediction inside = model.predict(123.0, 150.0);
  EXPECT_TRUE(inside.in_range);
  EXPECT_FALSE(inside.bearing_deg);
  EXPECT_NEAR(inside.distance_cm, 300.0, 1e-9);
  EXPECT_FALSE(model.predict(123.0, 70.0).in_range);
  EXPECT_FALSE(model.predict(123.0, 210.0).in_range);
  EXPECT_FALSE(model.robot_point_cm({319.5, 239.5 - 230.0}));  // outside the image too
}

// The trigonometry-free hot path equals Algorithm 1 with atan2, cos and sin.
TEST(PolynomialModel, FastConversionEqualsAlgorithm1) {
  std::vector<PolarSample> samples;
  for (double r = 60.0; r <= 220.0; r += 5.0) samples.push_back({0.0, r, 0.01 * r * r, {}});
  const PolynomialGroundModel model = fit_polynomial_model(samples, {}, {});
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> x(100.0, 540.0), y(20.0, 460.0);
  for (int i = 0; i < 1000; ++i) {
    const Vec2 pixel(x(rng), y(rng));
    const Polar polar = image_polar_from_pixel(pixel, model.domain().image.center_px);
    const Vec2 slow = robot_point_from_bearing(
        robot_bearing_deg_from_image_theta_deg(polar.theta_deg), model.polynomial()(polar.radius));
    EXPECT_NEAR((model.convert(pixel) - slow).norm(), 0.0, 1e-9) << pixel.transpose();
  }
}

TEST(PolynomialModel, RejectsTooFewDistinctRadiiAndBadDegree) {
  std::vector<PolarSample> samples;
  for (int i = 0; i < 10; ++i) samples.push_back({10.0 * i, 80.0 + (i % 3), 60.0, {}});
  EXPECT_NE(test::input_error([&] {
              fit_polynomial_model(samples, {}, {});
            }).find("needs at least 7 samples with distinct radii, got 3"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] { fit_polynomial_model(samples, {}, {0}); }).find("poly degree"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
