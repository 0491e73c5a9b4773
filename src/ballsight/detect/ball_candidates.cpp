#include "ballsight/detect/ball_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {

void BallCandidateOptions::validate() const {
  require(min_radius_px >= 1.0, "min_radius_px", "must be at least 1 pixel");
  require(max_radius_share > 0.0 && max_radius_share <= 1.0, "max_radius_share",
          "must be within (0, 1]");
  require(scales_per_octave >= 1 && scales_per_octave <= 8, "scales_per_octave",
          "must be within [1, 8]");
  require(min_response >= 0.0, "min_response", "must be 0 or more");
  require(max_candidates >= 1, "max_candidates", "must be at least 1");
}

namespace {

// The blur the image is taken to have already: half a pixel.
constexpr double kImageSigma = 0.5;

// The signed yellowness min(R, G) - B of every pixel.
cv::Mat1f yellowness_image(const cv::Mat& bgr) {
  cv::Mat1f out(bgr.size());
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* in = bgr.ptr<cv::Vec3b>(y);
    float* row = out.ptr<float>(y);
    for (int x = 0; x < bgr.cols; ++x)
      row[x] = static_cast<float>(std::min(in[x][1], in[x][2])) - static_cast<float>(in[x][0]);
  }
  return out;
}

void blur_to(const cv::Mat1f& from, double from_sigma, double to_sigma, cv::Mat1f& to) {
  const double sigma = std::sqrt(std::max(to_sigma * to_sigma - from_sigma * from_sigma, 0.01));
  cv::GaussianBlur(from, to, cv::Size(), sigma, sigma, cv::BORDER_REPLICATE);
}

// The parabola's vertex offset through (-1, a), (0, b), (1, c), within half a step.
double vertex(double a, double b, double c) {
  const double d = a - 2.0 * b + c;
  return d < 0.0 ? std::clamp(0.5 * (a - c) / d, -0.5, 0.5) : 0.0;
}

// Whether v exceeds its 26 neighbours in the three response images (the middle one holds v).
bool is_maximum(const cv::Mat1f& below, const cv::Mat1f& at, const cv::Mat1f& above, int x, int y,
                float v) {
  for (const cv::Mat1f* m : {&below, &at, &above}) {
    for (int dy = -1; dy <= 1; ++dy) {
      const float* row = m->ptr<float>(y + dy);
      for (int dx = -1; dx <= 1; ++dx) {
        if (m == &at && dx == 0 && dy == 0) continue;
        if (row[x + dx] >= v) return false;
      }
    }
  }
  return true;
}

}  // namespace

std::vector<BallCandidate> find_ball_candidates(const cv::Mat& bgr,
                                                const BallCandidateOptions& options) {
  options.validate();
  require(bgr.type() == CV_8UC3 && !bgr.empty(), "ball candidates", "need an 8-bit BGR image");
  const int s = options.scales_per_octave;
  const double k = std::pow(2.0, 1.0 / s);
  // A disc of radius r answers most at sigma r / sqrt(2); the first level searched is the
  // second of an octave.
  const double sigma0 = options.min_radius_px / std::sqrt(2.0) / k;
  const double max_radius = options.max_radius_share * std::min(bgr.cols, bgr.rows);

  std::vector<BallCandidate> out;
  cv::Mat1f base;
  blur_to(yellowness_image(bgr), kImageSigma, sigma0, base);
  std::vector<cv::Mat1f> blurred(static_cast<std::size_t>(s + 3));
  std::vector<cv::Mat1f> response(static_cast<std::size_t>(s + 2));
  for (double scale = 1.0;
       sigma0 * std::sqrt(2.0) * scale <= max_radius && std::min(base.cols, base.rows) >= 3;
       scale *= 2.0) {
    blurred[0] = base;
    for (int i = 1; i < s + 3; ++i)
      blur_to(blurred[static_cast<std::size_t>(i - 1)], sigma0 * std::pow(k, i - 1),
              sigma0 * std::pow(k, i), blurred[static_cast<std::size_t>(i)]);
    // Bright blobs: the finer blur minus the coarser, ~ -(k - 1) sigma^2 Laplacian.
    for (int i = 0; i < s + 2; ++i) {
      cv::subtract(blurred[static_cast<std::size_t>(i)], blurred[static_cast<std::size_t>(i + 1)],
                   response[static_cast<std::size_t>(i)]);
      response[static_cast<std::size_t>(i)] *= static_cast<float>(1.0 / (k - 1.0));
    }
    for (int i = 1; i <= s; ++i) {
      const cv::Mat1f& below = response[static_cast<std::size_t>(i - 1)];
      const cv::Mat1f& at = response[static_cast<std::size_t>(i)];
      const cv::Mat1f& above = response[static_cast<std::size_t>(i + 1)];
      for (int y = 1; y + 1 < at.rows; ++y) {
        const float* row = at.ptr<float>(y);
        for (int x = 1; x + 1 < at.cols; ++x) {
          const float v = row[x];
          if (v < options.min_response || !is_maximum(below, at, above, x, y, v)) continue;
          const double dx = vertex(row[x - 1], v, row[x + 1]);
          const double dy = vertex(at(y - 1, x), v, at(y + 1, x));
          const double di = vertex(below(y, x), v, above(y, x));
          const double radius = sigma0 * std::pow(k, i + di) * std::sqrt(2.0) * scale;
          if (radius > max_radius) continue;
          // A level halved n times keeps every 2^n-th pixel of the image (INTER_NEAREST).
          out.push_back({Vec2(scale * (x + dx), scale * (y + dy)), radius, v});
        }
      }
    }
    // The next octave starts from this one's blur of twice sigma0, halved.
    cv::resize(blurred[static_cast<std::size_t>(s)], base,
               cv::Size(std::max(1, blurred[0].cols / 2), std::max(1, blurred[0].rows / 2)), 0, 0,
               cv::INTER_NEAREST);
  }
  std::sort(out.begin(), out.end(),
            [](const BallCandidate& a, const BallCandidate& b) { return a.response > b.response; });
  if (out.size() > static_cast<std::size_t>(options.max_candidates))
    out.resize(static_cast<std::size_t>(options.max_candidates));
  return out;
}

}  // namespace ballsight
