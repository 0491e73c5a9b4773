#include "ballsight/eval/omni_data_floor.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ballsight/eval/omni_real.hpp"

namespace ballsight {
namespace {

// A field linear in the radius along every ray and linear in the angle between rays: the
// neighbours read it exactly wherever they bracket the sample.
double linear_field(double theta_deg, double radius_px) {
  return 2.0 * radius_px + 0.5 * theta_deg;
}

std::vector<PolarSample> samples_at(const std::vector<double>& thetas,
                                    const std::vector<double>& radii) {
  std::vector<PolarSample> out;
  for (const double t : thetas)
    for (const double r : radii) out.push_back({t, r, linear_field(t, r), std::nullopt});
  return out;
}

TEST(OmniDataFloor, ADirectionBetweenTwoIsReadInAngleAndAlongBothRays) {
  const std::vector<PolarSample> train = samples_at({10.0, 30.0, 50.0}, {100.0, 150.0, 200.0});
  // Between the rays, between and beyond their radii (the two nearest samples extrapolate).
  for (const double r : {120.0, 180.0, 230.0, 80.0}) {
    const std::optional<double> d =
        neighbour_distance_cm(train, {40.0, r, 0.0, std::nullopt}, HeldOutSplit::kDirections);
    ASSERT_TRUE(d.has_value()) << r;
    EXPECT_NEAR(*d, linear_field(40.0, r), 1e-9) << r;
  }
  // Across 0 deg: 340 deg behind, 10 deg ahead, read in the angle between them (a third of the
  // way).
  const std::vector<PolarSample> round = samples_at({10.0, 30.0, 340.0}, {100.0, 200.0});
  const std::optional<double> across_zero =
      neighbour_distance_cm(round, {350.0, 150.0, 0.0, std::nullopt}, HeldOutSplit::kDirections);
  ASSERT_TRUE(across_zero.has_value());
  const double behind = linear_field(340.0, 150.0), ahead = linear_field(10.0, 150.0);
  EXPECT_NEAR(*across_zero, behind + (ahead - behind) / 3.0, 1e-9);
  // Every training ray within half a turn ahead: the nearest of them is read.
  const std::optional<double> one_side =
      neighbour_distance_cm(train, {350.0, 150.0, 0.0, std::nullopt}, HeldOutSplit::kDirections);
  ASSERT_TRUE(one_side.has_value());
  EXPECT_NEAR(*one_side, linear_field(10.0, 150.0), 1e-9);
}

TEST(OmniDataFloor, AHeldOutDistanceIsReadAlongItsOwnRay) {
  const std::vector<PolarSample> train = samples_at({0.0, 90.0}, {100.0, 200.0, 300.0});
  const std::optional<double> d =
      neighbour_distance_cm(train, {90.0, 250.0, 0.0, std::nullopt}, HeldOutSplit::kDistance);
  ASSERT_TRUE(d.has_value());
  EXPECT_NEAR(*d, linear_field(90.0, 250.0), 1e-9);
  // A ray with one sample left cannot be read: the floor counts the sample as unmapped, its whole
  // distance its error, as a model's unmapped query is counted.
  const std::vector<PolarSample> one = samples_at({0.0}, {100.0});
  EXPECT_FALSE(
      neighbour_distance_cm(one, {0.0, 150.0, 0.0, std::nullopt}, HeldOutSplit::kDistance));
  const std::vector<HeldOutFold> folds{{one, {{0.0, 150.0, 300.0, std::nullopt}}}};
  std::size_t unmapped = 0;
  const ErrorSummary floor = neighbour_floor(folds, HeldOutSplit::kDistance, unmapped);
  EXPECT_EQ(unmapped, 1u);
  EXPECT_DOUBLE_EQ(floor.median, 300.0);
}

TEST(OmniDataFloor, TheFloorOfNoisyMeasurementsIsTheirNoise) {
  // Each direction of a linear field off by +1 or -1 cm in turn: a held-out direction and its two
  // neighbours are off in opposite ways, and the neighbours miss it by the noise's 2 cm swing.
  std::vector<PolarSample> samples = samples_at({0, 20, 40, 60, 80, 100, 120, 140}, {100, 200});
  for (std::size_t i = 0; i < samples.size(); ++i)
    samples[i].distance_cm += (i / 2) % 2 ? 1.0 : -1.0;
  std::size_t unmapped = 0;
  const ErrorSummary floor = neighbour_floor(held_out_folds(samples, HeldOutSplit::kDirections),
                                             HeldOutSplit::kDirections, unmapped);
  EXPECT_EQ(unmapped, 0u);
  EXPECT_NEAR(floor.median, 2.0, 1e-9);
}

// A set's result with the given medians on the direction split (floor last).
RealOmniSetResult medians(double poly, double mlp, double ours, double floor) {
  RealOmniSetResult set;
  const auto score = [](const char* method, double median) {
    HeldOutScore s{method, HeldOutSplit::kDirections, {}, 0, 0.0};
    s.distance_cm.median = median;
    return s;
  };
  set.scores = {score("poly", poly), score("paper-mlp", mlp), score("ballsight", ours)};
  set.floors = {score("floor", floor)};
  return set;
}

TEST(OmniRealTarget, SevenTenthsOfTheBetterBaselineOnlyWhereTheFloorAllowsIt) {
  // The floor below 0.7x the better baseline (3 cm): the limit is 2.1 cm.
  const auto low = omni_real_target(medians(5.0, 3.0, 2.0, 1.0), HeldOutSplit::kDirections);
  ASSERT_TRUE(low.has_value());
  EXPECT_TRUE(low->below_floor_rule);
  EXPECT_DOUBLE_EQ(low->limit_cm, 0.7 * 3.0);
  EXPECT_TRUE(low->met());
  EXPECT_FALSE(omni_real_target(medians(5.0, 3.0, 2.2, 1.0), HeldOutSplit::kDirections)->met());
  // The floor above it: within 1.1x the floor, and never above the better baseline.
  const auto near = omni_real_target(medians(5.0, 3.0, 2.4, 2.5), HeldOutSplit::kDirections);
  ASSERT_TRUE(near.has_value());
  EXPECT_FALSE(near->below_floor_rule);
  EXPECT_DOUBLE_EQ(near->limit_cm, 1.1 * 2.5);
  EXPECT_TRUE(near->met());
  EXPECT_DOUBLE_EQ(
      omni_real_target(medians(5.0, 3.0, 2.4, 2.9), HeldOutSplit::kDirections)->limit_cm, 3.0);
  // Without a baseline, or on a split with no score, there is no target.
  RealOmniSetResult no_mlp = medians(5.0, 3.0, 2.0, 1.0);
  no_mlp.scores.erase(no_mlp.scores.begin() + 1);
  EXPECT_FALSE(omni_real_target(no_mlp, HeldOutSplit::kDirections).has_value());
  EXPECT_FALSE(omni_real_target(medians(5.0, 3.0, 2.0, 1.0), HeldOutSplit::kDistance).has_value());
}

}  // namespace
}  // namespace ballsight
