#pragma once
// The colours of a floor: given the pixels of the blobs a photo's ball search took for floor (a
// court, a wooden floor, a wall of a ball's colours; photo_balls.cpp), the cells of the colour
// table (ColorClassTable::index) that are the floor's and no ball's. A ball the floor's blob
// swallowed stays below the mode share and is not joined to the floor's modes (its rim's mixed
// colours are too few in any cell); a ball holding 5 % of the floor's pixels in one cell would
// be taken for floor.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace ballsight {

class FloorColours {
 public:
  /// The floor's cells, from its pixels (indices y * width + x into the continuous 8-bit BGR
  /// image `bgr`), given in parts: its modes (cells of 5 % of the pixels or more), the cells of
  /// 0.1 % or more (and 10 pixels) joined to them in colour space (26-neighbours), then four
  /// rounds of the floor's other cells next to those (its noise and shading).
  std::vector<std::size_t> cells(const cv::Mat& bgr,
                                 const std::vector<const std::vector<int>*>& parts);

 private:
  std::vector<std::uint32_t> counts_;  // per cell (allocated at the first call), zero between calls
};

}  // namespace ballsight
