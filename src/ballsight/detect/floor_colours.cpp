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

}  // namespace

std::vector<std::size_t> FloorColours::cells(const cv::Mat& bgr,
                                             const std::vector<const std::vector<int>*>& parts) {
  counts_.resize(ColorClassTable::kTableSize, 0);
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
    constexpr int kLast = ColorClassTable::kCellsPerChannel - 1;
    const cv::Vec3i c = ColorClassTable::cell_channels(cell);
    for (int b = std::max(0, c[0] - 1); b <= std::min(kLast, c[0] + 1); ++b)
      for (int g = std::max(0, c[1] - 1); g <= std::min(kLast, c[1] + 1); ++g)
        for (int r = std::max(0, c[2] - 1); r <= std::min(kLast, c[2] + 1); ++r)
          if (counts_[ColorClassTable::cell(b, g, r)] == kFloor) return true;
    return false;
  };
  // One round of growth into the cells next to the floor (of `least_pixels` or more when
  // `common`); whether it grew.
  const double least_pixels = std::max(kCommonMinPixels, kCommonShare * static_cast<double>(total));
  const auto grow = [&](bool common) {
    std::vector<std::size_t> grown;
    for (const std::size_t cell : touched)
      if (counts_[cell] != kFloor && (!common || counts_[cell] >= least_pixels) &&
          next_to_floor(cell))
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
