#pragma once
// A learned verifier of ball candidates (ball_candidates.hpp): a small CNN that gives each
// candidate's patch (ball_patches.hpp) the probability that it is a ball. Trained offline by
// scripts/train_ball_verifier.py on patches written by `ballsight detect patches`, exported to
// ONNX and run through OpenCV's DNN module. What it adds to the photo detector is measured by
// `eval detect-real --verifier` (docs/detect-balls.md).

#include <array>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>
#include <span>
#include <string_view>
#include <vector>

#include "ballsight/detect/ball_candidates.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/detect/photo_balls.hpp"

namespace ballsight {

class BallVerifier {
 public:
  /// The model in ONNX bytes (input "patch": N x 3 x 32 x 32, BGR / 255; output: N logits);
  /// throws InputError, naming `where`, when they are no such model.
  BallVerifier(std::string_view onnx, const std::string& where);
  /// The model file at `path`.
  static BallVerifier read(const std::filesystem::path& path);

  /// Per candidate of the 8-bit BGR image: the probability (0-1) that it is a ball.
  std::vector<double> probabilities(const cv::Mat& bgr, std::span<const BallCandidate> candidates);

 private:
  cv::dnn::Net net_;
};

/// What the photo detector and the verifier make of one photo.
struct VerifiedPhoto {
  std::vector<PhotoBall> balls;
  std::vector<BallCandidate> candidates;
  std::vector<double> probability;  // per candidate
};

/// The photo's balls as the detector finds them and the verifier's candidates.
VerifiedPhoto verify_photo(PhotoBallDetector& detector, BallVerifier& verifier, const cv::Mat& bgr);
/// Every photo of a source, verify_photo'd.
std::vector<VerifiedPhoto> verify_photos(PhotoBallDetector& detector, BallVerifier& verifier,
                                         const LabelledPhotos& photos);

/// The photo detector's balls and, after them, each candidate of probability at least
/// `min_probability` (best first) that lies on no ball kept so far (centres farther apart than
/// the larger radius); an added ball's score is its probability.
std::vector<PhotoBall> with_verified_candidates(const VerifiedPhoto& seen, double min_probability);

/// The thresholds fit_min_probability chooses from; above 1, no candidate is added.
inline constexpr std::array<double, 7> kVerifierThresholds{0.9,     0.99,     0.999, 0.9999,
                                                           0.99999, 0.999999, 1.1};

/// The threshold of kVerifierThresholds of the best mean F1 over the sources (`seen[s]` is
/// verify_photos of `sources[s]`); the highest of equals.
double fit_min_probability(std::span<const LabelledPhotos> sources,
                           std::span<const std::vector<VerifiedPhoto>> seen);

}  // namespace ballsight
