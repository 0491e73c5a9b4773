#include "ballsight/detect/ball_patches.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {

cv::Mat ball_patch(const cv::Mat& bgr, const BallCandidate& candidate, int size) {
  require(bgr.type() == CV_8UC3 && !bgr.empty(), "ball patch", "needs an 8-bit BGR image");
  require(size >= 4, "ball patch", "size must be at least 4 pixels");
  const int side =
      std::max(4, static_cast<int>(std::lround(kBallPatchRadii * candidate.radius_px)));
  const int x0 = static_cast<int>(std::lround(candidate.center_px.x() - 0.5 * (side - 1)));
  const int y0 = static_cast<int>(std::lround(candidate.center_px.y() - 0.5 * (side - 1)));
  const cv::Rect window(x0, y0, side, side);
  const cv::Rect inside = window & cv::Rect(0, 0, bgr.cols, bgr.rows);
  cv::Mat crop;
  if (inside.empty()) {
    crop = cv::Mat(side, side, CV_8UC3, cv::Scalar::all(0));
  } else {
    cv::copyMakeBorder(bgr(inside), crop, inside.y - y0, window.br().y - inside.br().y,
                       inside.x - x0, window.br().x - inside.br().x, cv::BORDER_REPLICATE);
  }
  cv::Mat out;
  cv::resize(crop, out, cv::Size(size, size), 0, 0,
             side > size ? cv::INTER_AREA : cv::INTER_LINEAR);
  return out;
}

std::vector<CandidateTruth> candidate_truth(std::span<const BallCandidate> candidates,
                                            std::span<const LabelledBall> labels,
                                            std::span<const LabelledBall> ignored) {
  std::vector<CandidateTruth> out;
  out.reserve(candidates.size());
  const auto near = [](const BallCandidate& c, const LabelledBall& l) {
    return (c.center_px - l.center_px).norm() <= l.radius_px;
  };
  for (const BallCandidate& c : candidates) {
    CandidateTruth truth = CandidateTruth::not_ball;
    for (const LabelledBall& l : labels) {
      if (!near(c, l)) continue;
      const double ratio = c.radius_px / l.radius_px;
      truth = ratio >= 0.5 && ratio <= 2.0 ? CandidateTruth::ball : CandidateTruth::unknown;
      if (truth == CandidateTruth::ball) break;
    }
    if (truth == CandidateTruth::not_ball &&
        std::any_of(ignored.begin(), ignored.end(),
                    [&](const LabelledBall& l) { return near(c, l); }))
      truth = CandidateTruth::unknown;
    out.push_back(truth);
  }
  return out;
}

}  // namespace ballsight
