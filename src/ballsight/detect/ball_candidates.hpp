#pragma once
// Where a ball may be, at every size, with no colour threshold: the bright blobs of the image's
// yellowness min(R, G) - B (signed) found as the extrema of a difference-of-Gaussians scale space
// (Lindeberg's scale-normalised Laplacian, built octave by octave as in Lowe's SIFT). A disc of
// radius r answers most at sigma = r / sqrt(2), so each candidate has a radius as well as a
// centre. A pale ball on a grey floor is a weak blob, a saturated one on clay a strong one: the
// candidates are many and are sorted out by a verifier (ball_verifier.hpp), not by a threshold
// here (docs/detect-balls.md).

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct BallCandidate {
  Vec2 center_px = Vec2::Zero();
  double radius_px = 0.0;
  double response = 0.0;  // the scale-normalised blob response, in yellowness levels
};

struct BallCandidateOptions {
  double min_radius_px = 2.0;
  /// The largest radius looked for as a share of the image's short side.
  double max_radius_share = 0.25;
  int scales_per_octave = 3;
  double min_response = 2.0;
  /// At most this many, the strongest.
  int max_candidates = 400;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The candidates of an 8-bit BGR image, strongest first.
std::vector<BallCandidate> find_ball_candidates(const cv::Mat& bgr,
                                                const BallCandidateOptions& options = {});

}  // namespace ballsight
