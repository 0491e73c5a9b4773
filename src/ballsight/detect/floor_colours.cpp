#include "ballsight/detect/floor_colours.hpp"

#include <algorithm>
#include <limits>

#include "ballsight/detect/color_classes.hpp"

namespace ballsight {

namespace {

constexpr double kModeShare = 0.05;
constexpr double kCommonShare = 0.001;
constexpr double kCommonMinPixels = 10.0;
constexpr int kSpread = 4;
constexpr std::uint32_t kFloor = std::numeric_limits<std::uint32_t>::max();  // a counted cell
constexpr int kBits = ColorClassTable::kBits;
constexpr int kSide = 1 << kBits;

std::size_t cell_at(int b, int g, int r) {
  return (static_cast<std::size_t>(b) << (2 * kBits)) | (static_cast<std::size_t>(g) << kBits) |
         static_cast<std::size_t>(r);
}

}  // namespace

FloorColours::FloorColours() : counts_(ColorClassTable::kTableSize, 0) {}

std::vector<std::size_t> FloorColours::cells(const cv::Mat& bgr,
                                             const std::vector<const std::vector<int>*>& parts) {
  const auto* pixels = bgr.ptr<cv::Vec3b>(0);
  std::size_t total = 0;
  std::vector<std::size_t> touched;
  for (const std::vector<int>* part : parts) {
    total += part->size();
    for (int index : *part) {
      const std::size_t cell = ColorClassTable::index(pixels[index]);
      if (counts_[cell]++ == 0) touched.push_back(cell);
    }
  }
  std::vector<std::size_t> floor;
  for (const std::size_t cell : touched)
    if (counts_[cell] >= kModeShare * static_cast<double>(total))
      floor.push_back(cell), counts_[cell] = kFloor;
  const auto next_to_floor = [&](std::size_t cell) {
    const int b = static_cast<int>(cell >> (2 * kBits)),
              g = static_cast<int>(cell >> kBits) % kSide, r = static_cast<int>(cell) % kSide;
    for (int nb = std::max(0, b - 1); nb <= std::min(kSide - 1, b + 1); ++nb)
      for (int ng = std::max(0, g - 1); ng <= std::min(kSide - 1, g + 1); ++ng)
        for (int nr = std::max(0, r - 1); nr <= std::min(kSide - 1, r + 1); ++nr)
          if (counts_[cell_at(nb, ng, nr)] == kFloor) return true;
    return false;
  };
  // One round of growth into the cells next to the floor (of `least` pixels or more when
  // `common`); whether it grew.
  const double least = std::max(kCommonMinPixels, kCommonShare * static_cast<double>(total));
  const auto grow = [&](bool common) {
    std::vector<std::size_t> grown;
    for (const std::size_t cell : touched)
      if (counts_[cell] != kFloor && (!common || counts_[cell] >= least) && next_to_floor(cell))
        grown.push_back(cell);
    for (const std::size_t cell : grown) counts_[cell] = kFloor;
    floor.insert(floor.end(), grown.begin(), grown.end());
    return !grown.empty();
  };
  while (grow(true)) {
  }
  for (int round = 0; round < kSpread; ++round) grow(false);
  for (const std::size_t cell : touched) counts_[cell] = 0;
  return floor;
}

}  // namespace ballsight
