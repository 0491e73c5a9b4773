#include "ballsight/world/collection_sites.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TEST(CollectionSites, BallsWithinTheCollectorWidthFormOneSiteAndKeepTheirBalls) {
  const std::vector<Vec2> balls{{0, 0}, {0.3, 0.1}, {0.1, 0.5}, {5, 5}};
  const auto sites = collection_sites(balls, 0.70);
  ASSERT_EQ(sites.size(), 2u);
  EXPECT_EQ(sites[0].balls, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(sites[1].balls, (std::vector<int>{3}));
  EXPECT_LT((sites[0].center_m - Vec2(0.4 / 3, 0.2)).norm(), 1e-12);
}

// A chain of balls 50 cm apart is not one site (complete linkage, not a chain).
TEST(CollectionSites, ChainsDoNotGrowBeyondTheCollector) {
  const std::vector<Vec2> chain{{0, 0}, {0.5, 0}, {1.0, 0}, {1.5, 0}};
  for (const CollectionSite& site : collection_sites(chain, 0.70)) EXPECT_LE(site.diameter_m, 0.70);
}

// Random fields: every ball in exactly one site, every site within the width.
TEST(CollectionSites, PartitionProperty) {
  const std::uint64_t seed = 21;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 4.0);
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
    std::vector<Vec2> balls(40);
    for (Vec2& b : balls) b = Vec2(u(rng), u(rng));
    std::vector<int> count(balls.size(), 0);
    for (const CollectionSite& site : collection_sites(balls, 0.70)) {
      EXPECT_LE(site.diameter_m, 0.70 + 1e-12);
      for (int b : site.balls) ++count[static_cast<size_t>(b)];
    }
    for (int c : count) EXPECT_EQ(c, 1);
  }
}

TEST(CollectionSites, WidthMustBePositive) {
  EXPECT_THROW(collection_sites({{0, 0}}, 0.0), InputError);
}

}  // namespace
}  // namespace ballsight
