#pragma once
// The colours of a floor: given the pixels of the blobs a photo's ball search took for floor (a
// court, a wooden floor, a wall of a ball's colours; photo_balls.cpp), the cells of the colour
// table (ColorClassTable::index) that are the floor's and no ball's. A ball the floor's blob
// swallowed is a colour mode of its own, not joined to the floor's.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace ballsight {

class FloorColours {
 public:
  FloorColours();

  /// The floor's cells, from its pixels (indices y * width + x into the continuous 8-bit BGR
  /// image `bgr`), given in parts: its modes (cells of 5 % of the pixels or more), the cells of
  /// 0.1 % or more (and 10 pixels) joined to them in colour space (26-neighbours), then four
  /// rounds of the floor's other cells next to those (its noise and shading).
  std::vector<std::size_t> cells(const cv::Mat& bgr,
                                 const std::vector<const std::vector<int>*>& parts);

 private:
  std::vector<std::uint32_t> counts_;  // per cell, zero between calls
};

}  // namespace ballsight
