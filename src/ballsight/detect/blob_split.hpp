#pragma once
// Splitting a blob of touching objects into its parts: weighted k-means (Lloyd's algorithm) on the
// blob's evidence pixels, started from mutually farthest strong pixels. For touching discs of one
// size the boundary between two k-means cells is the line where the discs touch, so every part is
// one disc and its weighted centroid is that disc's centre.

#include <vector>

#include "ballsight/detect/blob_evidence.hpp"

namespace ballsight {

struct BlobPart {
  std::vector<EvidencePixel> pixels;
  double mass = 0.0;
  Vec2 centroid = Vec2::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
};

/// `count` parts (fewer when the blob has fewer pixels); a part may end up empty of mass only if
/// the pixels are degenerate, and is then dropped.
std::vector<BlobPart> split_blob(const std::vector<EvidencePixel>& pixels, int count,
                                 int iterations = 12);

}  // namespace ballsight
