#pragma once
// Sub-pixel measurement of a grown colour blob: how much more of the object's colour each pixel
// around it holds than the local background. The evidence is linear in the colour (a weighted sum
// of B, G, R whose weights add up to zero, so grey lines and ground give none), so a pixel half
// covered by the object holds half the evidence of a covered one and the weighted centroid is the
// centroid of the coverage, to a fraction of a pixel, without a colour conversion. On a floor
// whose colour leans towards the object's (a yellow ball on a wooden floor or a red court, and a
// little on the green court) the weights are taken across the floor's chroma: the floor then
// holds no evidence however bright, and a ball's shaded side, darker than the sunlit floor around
// it, still holds its own.

#include <limits>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/detect/blob_growth.hpp"

namespace ballsight {

/// One pixel near a blob and its evidence above the background (> 0).
struct EvidencePixel {
  float x = 0.0f, y = 0.0f;
  float weight = 0.0f;
};

struct BlobEvidence {
  std::vector<EvidencePixel> pixels;  // the blob and its 1-pixel border, positive evidence only
  double mass = 0.0;                  // sum of the weights
  double peak = 0.0;                  // largest weight
  Vec2 centroid = Vec2::Zero();       // weighted centroid
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  // weighted second central moments
  cv::Vec3b peak_bgr;           // colour of the pixel of largest evidence (the most covered one)
  double background = 0.0;      // background evidence (median on a ring around the blob, >= 0)
  double noise_sigma = 0.0;     // pixel noise of the evidence (from ring neighbours), >= 1
  int blob_area_px = 0;         // pixels of the grown blob itself
  bool touches_border = false;  // the blob reaches the image border
};

/// Measures `blob` in the 8-bit BGR image with evidence weights `evidence_bgr` (B, G, R: the
/// object's chroma direction, adding up to zero); the background ring lies `margin_px` outside the
/// blob's bounding box, and its median colour is the floor's. nullopt, before the blob's
/// support is measured, when its own pixels hold more evidence than `max_peaks` times the most
/// any pixel could hold (any colour, the same background): its mass is more than `max_peaks`
/// times its peak, whatever the peak. A floor of the object's colour then costs a pass over a
/// part of its pixels.
std::optional<BlobEvidence> measure_blob_evidence(
    const cv::Mat& bgr, const GrownBlob& blob, const cv::Vec3f& evidence_bgr, int margin_px,
    double max_peaks = std::numeric_limits<double>::infinity());

/// Weighted centroid and second central moments of `pixels` (mass 0: centroid and moments 0).
void weighted_moments(const std::vector<EvidencePixel>& pixels, double& mass, Vec2& centroid,
                      Eigen::Matrix2d& covariance);

}  // namespace ballsight
