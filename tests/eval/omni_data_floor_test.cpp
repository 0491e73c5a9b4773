#include "ballsight/eval/omni_data_floor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace ballsight {
namespace {

// A field linear in the angle between rays and curved along each ray (a mirror's distance grows
// faster than its radius): a reading between the wrong two radii, or of the wrong rays, is off.
double field(double theta_deg, double radius_px) {
  return 0.01 * radius_px * radius_px + 0.5 * theta_deg;
}

// The samples of `thetas` x `radii`, in a shuffled order.
std::vector<PolarSample> samples_at(const std::vector<double>& thetas,
                                    const std::vector<double>& radii) {
  std::vector<PolarSample> out;
  for (const double t : thetas)
    for (const double r : radii) out.push_back({t, r, field(t, r), std::nullopt});
  std::reverse(out.begin(), out.end());
  std::rotate(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(out.size() / 3), out.end());
  return out;
}

// The straight line through two samples of one ray, read at `r`.
double chord(double theta, double r0, double r1, double r) {
  return field(theta, r0) + (field(theta, r1) - field(theta, r0)) * (r - r0) / (r1 - r0);
}

std::optional<double> read_direction(const std::vector<PolarSample>& train, double theta,
                                     double r) {
  return neighbour_distance_cm(train, {theta, r, 0.0, std::nullopt}, HeldOutSplit::kDirections);
}

TEST(OmniDataFloor, ADirectionBetweenTwoIsReadInAngleAndAlongBothRays) {
  const std::vector<PolarSample> train = samples_at({10.0, 30.0, 50.0}, {100.0, 150.0, 200.0});
  // Between the two radii that bracket it (the rays' chords there), and beyond the end through
  // the two nearest; halfway between 30 and 50 deg.
  const std::vector<std::array<double, 3>> cases{
      {120.0, 100.0, 150.0}, {180.0, 150.0, 200.0}, {230.0, 150.0, 200.0}, {80.0, 100.0, 150.0}};
  for (const auto& [r, r0, r1] : cases) {
    const std::optional<double> d = read_direction(train, 40.0, r);
    ASSERT_TRUE(d.has_value()) << r;
    EXPECT_NEAR(*d, 0.5 * (chord(30.0, r0, r1, r) + chord(50.0, r0, r1, r)), 1e-9) << r;
  }
  // A quarter of the way from 30 to 50 deg.
  const std::optional<double> quarter = read_direction(train, 35.0, 150.0);
  ASSERT_TRUE(quarter.has_value());
  EXPECT_NEAR(*quarter, 0.75 * field(30.0, 150.0) + 0.25 * field(50.0, 150.0), 1e-9);
  // Across 0 deg: 340 deg behind, 10 deg ahead, read a third of the way from 340 to 10.
  const std::vector<PolarSample> round = samples_at({10.0, 30.0, 340.0}, {100.0, 200.0});
  const std::optional<double> across_zero = read_direction(round, 350.0, 200.0);
  ASSERT_TRUE(across_zero.has_value());
  EXPECT_NEAR(*across_zero, field(340.0, 200.0) + (field(10.0, 200.0) - field(340.0, 200.0)) / 3.0,
              1e-9);
  // Every training ray within half a turn ahead: the nearest of them is read alone.
  const std::optional<double> one_side = read_direction(train, 350.0, 150.0);
  ASSERT_TRUE(one_side.has_value());
  EXPECT_NEAR(*one_side, field(10.0, 150.0), 1e-9);
  // A held-out direction the folds cannot tell from a training one (0.0004 deg off) is that ray.
  const std::optional<double> same = read_direction(train, 30.0004, 150.0);
  ASSERT_TRUE(same.has_value());
  EXPECT_NEAR(*same, field(30.0, 150.0), 1e-9);
}

TEST(OmniDataFloor, AHeldOutDistanceIsReadAlongItsOwnRay) {
  std::vector<PolarSample> train = samples_at({0.0, 90.0}, {100.0, 200.0, 300.0});
  const auto read = [&](double r) {
    return neighbour_distance_cm(train, {90.0, r, 0.0, std::nullopt}, HeldOutSplit::kDistance);
  };
  ASSERT_TRUE(read(250.0).has_value());
  EXPECT_NEAR(*read(250.0), chord(90.0, 200.0, 300.0, 250.0), 1e-9);
  // Two samples at one radius are one point, their mean.
  train.push_back({90.0, 200.0, field(90.0, 200.0) + 4.0, std::nullopt});
  ASSERT_TRUE(read(250.0).has_value());
  EXPECT_NEAR(*read(250.0), chord(90.0, 200.0, 300.0, 250.0) + 1.0, 1e-9);
  // A ray with one radius left cannot be read: the floor counts the sample as unmapped, its whole
  // distance its error, as a model's unmapped query is counted.
  const std::vector<PolarSample> one{{0.0, 100.0, 100.0, std::nullopt},
                                     {0.0, 100.0, 104.0, std::nullopt}};
  EXPECT_FALSE(
      neighbour_distance_cm(one, {0.0, 150.0, 0.0, std::nullopt}, HeldOutSplit::kDistance));
  const std::vector<HeldOutFold> folds{{one, {{0.0, 150.0, 300.0, std::nullopt}}}};
  std::size_t unmapped = 0;
  const ErrorSummary floor = neighbour_floor(folds, HeldOutSplit::kDistance, unmapped);
  EXPECT_EQ(unmapped, 1u);
  EXPECT_DOUBLE_EQ(floor.median, 300.0);
}

TEST(OmniDataFloor, NoisyMeasurementsRaiseTheFloorAboveTheirNoise) {
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

}  // namespace
}  // namespace ballsight
