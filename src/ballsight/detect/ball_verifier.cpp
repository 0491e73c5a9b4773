#include "ballsight/detect/ball_verifier.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <numeric>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/detect/ball_patches.hpp"
#include "ballsight/detect/onnx_sizes.hpp"

namespace ballsight {

BallVerifier::BallVerifier(std::string_view onnx, const std::string& where) {
  check_onnx_sizes(onnx, where);
  try {
    net_ = cv::dnn::readNetFromONNX(onnx.data(), onnx.size());
  } catch (const cv::Exception&) {
    throw InputError(where + ": is no ONNX model OpenCV can read");
  } catch (const std::bad_alloc&) {
    throw InputError(where + ": asks for more memory than there is (a corrupt model?)");
  }
  require(!net_.empty(), where, "holds an empty ONNX model");
  // The model must take patches and give one number each.
  const cv::Mat probe(kBallPatchSize, kBallPatchSize, CV_8UC3, cv::Scalar::all(128));
  try {
    probabilities(probe, std::vector<BallCandidate>{{Vec2(16.0, 16.0), 8.0, 1.0},
                                                    {Vec2(8.0, 8.0), 4.0, 1.0}});
  } catch (const std::exception&) {
    throw InputError(where + ": takes no N x 3 x 32 x 32 patches to N logits");
  }
}

BallVerifier BallVerifier::read(const std::filesystem::path& path) {
  return BallVerifier(read_file(path, std::uintmax_t{64} << 20), path.string());
}

std::vector<double> BallVerifier::probabilities(const cv::Mat& bgr,
                                                std::span<const BallCandidate> candidates) {
  if (candidates.empty()) return {};
  std::vector<cv::Mat> patches;
  patches.reserve(candidates.size());
  for (const BallCandidate& c : candidates) patches.push_back(ball_patch(bgr, c));
  net_.setInput(cv::dnn::blobFromImages(patches, 1.0 / 255.0));
  const cv::Mat logits = net_.forward();
  require(logits.total() == candidates.size() && logits.depth() == CV_32F, "ball verifier",
          "gives no logit per patch");
  std::vector<double> out(candidates.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = 1.0 / (1.0 + std::exp(-static_cast<double>(logits.ptr<float>()[i])));
  return out;
}

std::vector<PhotoBall> with_verified_candidates(const VerifiedPhoto& seen, double min_probability) {
  const std::vector<BallCandidate>& candidates = seen.candidates;
  const std::vector<double>& probability = seen.probability;
  require(probability.size() == candidates.size(), "verified candidates",
          "need one probability per candidate");
  std::vector<PhotoBall> balls = seen.balls;
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return probability[a] > probability[b]; });
  for (const std::size_t i : order) {
    if (probability[i] < min_probability) break;
    const BallCandidate& c = candidates[i];
    const bool free = std::none_of(balls.begin(), balls.end(), [&](const PhotoBall& b) {
      return (b.center_px - c.center_px).norm() <= std::max(b.radius_px, c.radius_px);
    });
    if (free) balls.push_back({c.center_px, c.radius_px, probability[i]});
  }
  return balls;
}

VerifiedPhoto verify_photo(PhotoBallDetector& detector, BallVerifier& verifier,
                           const cv::Mat& bgr) {
  VerifiedPhoto seen{detector.detect(bgr), find_ball_candidates(bgr), {}};
  seen.probability = verifier.probabilities(bgr, seen.candidates);
  return seen;
}

std::vector<VerifiedPhoto> verify_photos(PhotoBallDetector& detector, BallVerifier& verifier,
                                         const LabelledPhotos& photos) {
  std::vector<VerifiedPhoto> out;
  for (const cv::Mat& bgr : photos.images) out.push_back(verify_photo(detector, verifier, bgr));
  return out;
}

double fit_min_probability(std::span<const LabelledPhotos> sources,
                           std::span<const std::vector<VerifiedPhoto>> seen) {
  require(sources.size() == seen.size() && !sources.empty(), "verifier threshold",
          "needs the verified photos of at least one source");
  double best = kVerifierThresholds.back();
  double best_f1 = -1.0;
  for (auto t = kVerifierThresholds.rbegin(); t != kVerifierThresholds.rend(); ++t) {
    double f1 = 0.0;
    for (std::size_t s = 0; s < sources.size(); ++s) {
      const BallMatch total = score_photos(
          sources[s], [&](std::size_t i) { return with_verified_candidates(seen[s][i], *t); });
      f1 += f1_score(total) / static_cast<double>(sources.size());
    }
    if (f1 > best_f1) {
      best_f1 = f1;
      best = *t;
    }
  }
  return best;
}

}  // namespace ballsight
