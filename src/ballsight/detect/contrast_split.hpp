#pragma once
// Balls on a surface of their own hue (a stock photo's indoor green court at hue 60-76 deg, its
// balls at 62-68 deg): the surface and the balls grow into one blob, and no hue band parts them.
// The balls are brighter and more saturated than such a surface, so their yellowness
// min(R, G) - B is higher (docs/detect-balls.md). A blob is split at Otsu's threshold of its
// pixels' yellowness into the connected parts of its brighter class, when the split is clear.

#include <algorithm>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/detect/blob_growth.hpp"

namespace ballsight {

/// When a blob is split: the two classes' means lie `min_contrast` or more apart and the brighter
/// class is at most `max_share` of the blob.
struct ContrastSplit {
  double min_contrast = 40.0;  // 0-255
  double max_share = 0.3;      // 0-1
};

/// How yellow a pixel is: min(R, G) - B, 0 at the least.
inline int yellowness(const cv::Vec3b& p) {
  return std::max(0, std::min(p[1], p[2]) - p[0]);
}

struct ContrastParts {
  int threshold = 0;             // the brighter class's least yellowness
  std::vector<GrownBlob> parts;  // its 4-connected parts of min_part_pixels or more
};

/// The split of `blob` (pixels of the continuous 8-bit BGR image `bgr`), or nothing when it is
/// not clear (`split`).
std::optional<ContrastParts> split_by_contrast(const cv::Mat& bgr, const GrownBlob& blob,
                                               const ContrastSplit& split,
                                               std::size_t min_part_pixels);

}  // namespace ballsight
