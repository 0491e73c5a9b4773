#pragma once
// What a verifier of ball candidates (ball_candidates.hpp) looks at: each candidate's square
// window of four radii, centred on it and resized to a fixed size, so that a ball fills the middle
// half of its patch at every size; and, for training and scoring, which candidates are balls by
// the labels of a photo (ball_labels.hpp).

#include <opencv2/core.hpp>
#include <span>
#include <vector>

#include "ballsight/detect/ball_candidates.hpp"
#include "ballsight/detect/ball_labels.hpp"

namespace ballsight {

inline constexpr int kBallPatchSize = 32;
/// A patch's side in candidate radii.
inline constexpr double kBallPatchRadii = 4.0;

/// The candidate's window in the 8-bit BGR image, resized to size x size (area averaging down,
/// bilinear up);
/// outside the image the border pixels are repeated.
cv::Mat ball_patch(const cv::Mat& bgr, const BallCandidate& candidate, int size = kBallPatchSize);

enum class CandidateTruth { ball, not_ball, unknown };

/// Per candidate: a ball when its centre lies within a label's radius and its radius within a
/// factor of two of the label's; unknown when it is on an ignored object or near a label but of
/// another size; otherwise not a ball.
std::vector<CandidateTruth> candidate_truth(std::span<const BallCandidate> candidates,
                                            std::span<const LabelledBall> labels,
                                            std::span<const LabelledBall> ignored);

}  // namespace ballsight
