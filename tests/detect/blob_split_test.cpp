#include "ballsight/detect/blob_split.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace ballsight {
namespace {

// Unit-weight evidence on every pixel centre that `inside` holds, over a 60 x 40 window.
std::vector<EvidencePixel> raster(const std::function<bool(const Vec2&)>& inside) {
  std::vector<EvidencePixel> pixels;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 60; ++x)
      if (inside(Vec2(x, y)))
        pixels.push_back({static_cast<float>(x), static_cast<float>(y), 1.0f});
  return pixels;
}

// Two touching discs: each part is one disc, its centroid the disc's centre.
TEST(BlobSplit, TouchingDiscsSplitIntoTheirCentres) {
  const Vec2 a(20.3, 20.1), b(36.3, 20.1);
  const auto pixels =
      raster([&](const Vec2& p) { return (p - a).norm() <= 8.0 || (p - b).norm() <= 8.0; });
  const auto parts = split_blob(pixels, 2);
  ASSERT_EQ(parts.size(), 2u);
  const bool a_first = (parts[0].centroid - a).norm() < (parts[1].centroid - a).norm();
  EXPECT_LT((parts[a_first ? 0 : 1].centroid - a).norm(), 0.5);
  EXPECT_LT((parts[a_first ? 1 : 0].centroid - b).norm(), 0.5);
}

// Fewer pixels than parts asked for: as many parts as pixels.
TEST(BlobSplit, FewerPixelsThanPartsGiveFewerParts) {
  const std::vector<EvidencePixel> pixels = {{1.0f, 1.0f, 1.0f}, {5.0f, 1.0f, 1.0f}};
  EXPECT_EQ(split_blob(pixels, 3).size(), 2u);
}

}  // namespace
}  // namespace ballsight
