#pragma once
// The balls in one colour blob of a photo, with no camera model: a blob holds one ball, a few
// touching or hiding each other, or none (foliage, a cone, a line). Circles are proposed at the
// maxima of the blob's distance transform, largest first (each one explains its part of the
// blob), refined by a geometric circle fit to the blob's own outline (the parts of the outline
// nearest each circle), and scored by how much of the circle's outline the blob shows, how full
// the disc is and how empty the ring around it is. Edges on the image border and outline hidden
// by a neighbouring circle count neither for nor against a circle.

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct BlobCircle {
  Vec2 center_px = Vec2::Zero();  // image pixels (pixel centres at integers)
  double radius_px = 0.0;
  double score = 0.0;  // 0-1: outline support x disc fill x ring emptiness
};

struct BlobCircleOptions {
  double min_radius_px = 2.0;
  double max_radius_px = 150.0;
  double min_score = 0.35;
};

/// A blob's filled mask (255 inside) over part of an image: mask pixel (x, y) is image pixel
/// origin + (x, y).
struct BlobMask {
  cv::Mat1b mask;
  Vec2 origin = Vec2::Zero();
  cv::Size image_size;  // the whole image's

  Vec2 to_image(double x, double y) const { return origin + Vec2(x, y); }
  /// Whether the image point `q` lies in the blob (nearest mask pixel).
  bool contains(const Vec2& q) const;
};

/// Circles in a blob, in image pixels.
std::vector<BlobCircle> circles_in_blob(const BlobMask& blob, const BlobCircleOptions& options);

/// The narrowest a clump's blob may be between two touching balls: this share of its width
/// through either centre (two touching discs: 0 to 0.6).
inline constexpr double kClumpNeck = 0.75;

/// Whether the blob's circles are a clump of touching balls: between every two that touch
/// (centres within the sum of the radii and a pixel; at least two do) the blob narrows to a neck
/// of at most kClumpNeck of its width through either centre, across the line joining them, where
/// their outlines cross. A painted line or an elongated leaf split into a row of circles has no
/// neck.
bool is_clump(const BlobMask& blob, const std::vector<BlobCircle>& circles);

}  // namespace ballsight
