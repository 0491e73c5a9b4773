#include "ballsight/calib/held_out_folds.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace ballsight {
namespace {

// 8 directions x 5 distances.
std::vector<PolarSample> grid() {
  std::vector<PolarSample> samples;
  for (int t = 0; t < 8; ++t) {
    for (int d = 1; d <= 5; ++d) samples.push_back({45.0 * t, 20.0 * d, 50.0 * d, std::nullopt});
  }
  return samples;
}

TEST(HeldOutFolds, DirectionsAlternateAndEverySampleIsHeldOutOnce) {
  const std::vector<HeldOutFold> folds = held_out_folds(grid(), HeldOutSplit::kDirections);
  ASSERT_EQ(folds.size(), 2u);
  std::size_t held_out = 0;
  for (const HeldOutFold& fold : folds) {
    EXPECT_EQ(fold.train.size() + fold.test.size(), 40u);
    for (const PolarSample& test : fold.test) {
      EXPECT_TRUE(std::none_of(fold.train.begin(), fold.train.end(), [&](const PolarSample& s) {
        return s.theta_deg == test.theta_deg;
      }));
    }
    held_out += fold.test.size();
  }
  EXPECT_EQ(held_out, 40u);
  EXPECT_EQ(folds[0].test.front().theta_deg, 0.0);
  EXPECT_EQ(folds[1].test.front().theta_deg, 45.0);
}

TEST(HeldOutFolds, EachInteriorDistanceIsHeldOutWhole) {
  const std::vector<HeldOutFold> folds = held_out_folds(grid(), HeldOutSplit::kDistance);
  ASSERT_EQ(folds.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(folds[i].test.size(), 8u);
    for (const PolarSample& s : folds[i].test) EXPECT_EQ(s.distance_cm, 100.0 + 50.0 * i);
    for (const PolarSample& s : folds[i].train) EXPECT_NE(s.distance_cm, 100.0 + 50.0 * i);
  }
}

TEST(HeldOutFolds, NoFoldsWhereNothingCanBeHeldOut) {
  std::vector<PolarSample> one_direction;
  for (int d = 1; d <= 2; ++d) one_direction.push_back({90.0, 20.0 * d, 50.0 * d, std::nullopt});
  EXPECT_TRUE(held_out_folds(one_direction, HeldOutSplit::kDirections).empty());
  EXPECT_TRUE(held_out_folds(one_direction, HeldOutSplit::kDistance).empty());
}

TEST(HeldOutFolds, SpreadKeepsTheEndsAndTheMiddle) {
  std::vector<PolarSample> samples;
  for (int d = 1; d <= 12; ++d) samples.push_back({90.0, 10.0 * d, 25.0 * d, std::nullopt});
  const std::vector<HeldOutFold> folds =
      spread_folds(held_out_folds(samples, HeldOutSplit::kDistance), 3);
  ASSERT_EQ(folds.size(), 3u);
  EXPECT_EQ(folds[0].test.front().distance_cm, 50.0);
  EXPECT_EQ(folds[1].test.front().distance_cm, 150.0);
  EXPECT_EQ(folds[2].test.front().distance_cm, 275.0);
}

}  // namespace
}  // namespace ballsight
