#include "ballsight/core/angle.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ballsight {
namespace {

TEST(FastAtan2, WithinTenMicroradiansOfTheLibraryEverywhere) {
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double angle = -kPi + 2.0 * kPi * i / 20000.0;
    for (const double r : {1e-6, 0.3, 1.0, 250.0}) {
      const double y = r * std::sin(angle), x = r * std::cos(angle);
      worst = std::max(worst, std::abs(fast_atan2(y, x) - std::atan2(y, x)));
    }
  }
  EXPECT_LT(worst, 1e-5);
  EXPECT_EQ(fast_atan2(0.0, 0.0), 0.0);
  EXPECT_NEAR(fast_atan2(0.0, -1.0), kPi, 1e-12);
  EXPECT_NEAR(fast_atan2(-1.0, 0.0), -kPi / 2.0, 1e-12);
}

}  // namespace
}  // namespace ballsight
