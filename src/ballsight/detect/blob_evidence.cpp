#include "ballsight/detect/blob_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "ballsight/core/statistics.hpp"

namespace ballsight {

void weighted_moments(const std::vector<EvidencePixel>& pixels, double& mass, Vec2& centroid,
                      Eigen::Matrix2d& covariance) {
  double m = 0.0, sx = 0.0, sy = 0.0;
  for (const EvidencePixel& p : pixels) {
    m += p.weight;
    sx += p.weight * p.x;
    sy += p.weight * p.y;
  }
  mass = m;
  centroid = Vec2::Zero();
  covariance = Eigen::Matrix2d::Zero();
  if (m <= 0.0) return;
  centroid = Vec2(sx / m, sy / m);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (const EvidencePixel& p : pixels) {
    const double dx = p.x - centroid.x(), dy = p.y - centroid.y();
    sxx += p.weight * dx * dx;
    sxy += p.weight * dx * dy;
    syy += p.weight * dy * dy;
  }
  covariance << sxx / m, sxy / m, sxy / m, syy / m;
}

namespace {

// A floor whose chroma (its colour less its grey) is shorter than this is grey: its direction is
// noise.
constexpr double kMinFloorChroma = 10.0;
// The share of the object's chroma direction that must lie off the floor's for the evidence to
// be taken across the floor's (a blue marker on a blue court keeps its own weights).
constexpr double kMinOwnChromaOffFloor = 0.5;

// The evidence weights for an object of weights `own` on a floor of colour `floor_colour`: where
// the floor's chroma leans towards the object's (a wooden floor or a red court under a yellow
// ball, and a little the green court), the component of `own` across the floor's chroma, as long
// as `own`, so that the floor holds no evidence at any brightness and a ball's shaded side, darker
// than the sunlit floor, still holds its own; else `own`. Both add up to zero.
cv::Vec3f weights_across_floor(const cv::Vec3f& own, const cv::Vec3f& floor_colour) {
  const cv::Vec3f chroma =
      floor_colour - cv::Vec3f::all((floor_colour[0] + floor_colour[1] + floor_colour[2]) / 3.0f);
  const double length = cv::norm(chroma);
  if (length < kMinFloorChroma) return own;
  const cv::Vec3f along = chroma / static_cast<float>(length);
  const float shared = own.dot(along);
  const cv::Vec3f across = own - shared * along;
  const double own_length = cv::norm(own), kept = cv::norm(across);
  if (shared <= 0.0f || kept < kMinOwnChromaOffFloor * own_length) return own;
  return across * static_cast<float>(own_length / kept);
}

// The pixels of the window's outer ring, walked in order.
std::vector<cv::Vec3b> window_ring(const cv::Mat& bgr, const cv::Rect& window) {
  std::vector<cv::Vec3b> ring;
  const int x0 = window.x, y0 = window.y, x1 = window.br().x - 1, y1 = window.br().y - 1;
  for (int x = x0; x < x1; ++x) ring.push_back(bgr.at<cv::Vec3b>(y0, x));
  for (int y = y0; y < y1; ++y) ring.push_back(bgr.at<cv::Vec3b>(y, x1));
  for (int x = x1; x > x0; --x) ring.push_back(bgr.at<cv::Vec3b>(y1, x));
  for (int y = y1; y > y0; --y) ring.push_back(bgr.at<cv::Vec3b>(y, x0));
  return ring;
}

}  // namespace

std::optional<BlobEvidence> measure_blob_evidence(const cv::Mat& bgr, const GrownBlob& blob,
                                                  const cv::Vec3f& evidence_bgr, int margin_px,
                                                  double max_peaks) {
  BlobEvidence out;
  out.blob_area_px = static_cast<int>(blob.pixels.size());
  const cv::Rect image(0, 0, bgr.cols, bgr.rows);
  out.touches_border = blob.bbox.x == 0 || blob.bbox.y == 0 || blob.bbox.br().x == bgr.cols ||
                       blob.bbox.br().y == bgr.rows;
  const cv::Rect window =
      cv::Rect(blob.bbox.x - margin_px, blob.bbox.y - margin_px, blob.bbox.width + 2 * margin_px,
               blob.bbox.height + 2 * margin_px) &
      image;
  // The floor: the median colour, channel by channel, of the window's outer ring.
  const std::vector<cv::Vec3b> ring_pixels = window_ring(bgr, window);
  cv::Vec3f floor_colour;
  for (int c = 0; c < 3; ++c) {
    std::vector<float> channel;
    channel.reserve(ring_pixels.size());
    for (const cv::Vec3b& p : ring_pixels) channel.push_back(p[c]);
    floor_colour[c] = static_cast<float>(median(std::move(channel)));
  }
  const cv::Vec3f weights = weights_across_floor(evidence_bgr, floor_colour);
  const auto evidence_of = [&](const cv::Vec3b& p) {
    return weights[0] * p[0] + weights[1] * p[1] + weights[2] * p[2];
  };
  const auto evidence = [&](int x, int y) { return evidence_of(bgr.at<cv::Vec3b>(y, x)); };

  // Background: the median evidence on the ring; never below grey (0), so that grey things
  // beside the object (the robot's box, a line) count as background even on a background of
  // negative evidence. Noise: from differences of ring neighbours, which an edge crossing the
  // ring hardly changes.
  std::vector<float> ring;
  ring.reserve(ring_pixels.size());
  for (const cv::Vec3b& p : ring_pixels) ring.push_back(evidence_of(p));
  std::vector<float> steps(ring.size());
  for (size_t i = 0; i < ring.size(); ++i)
    steps[i] = std::abs(ring[i] - ring[(i + 1) % ring.size()]);
  out.noise_sigma = std::max(1.0, 1.4826 / std::numbers::sqrt2 * median(std::move(steps)));
  out.background = std::max(0.0, median(std::move(ring)));

  // The blob's own pixels are part of its support: their evidence is a lower bound of its mass.
  // The most a pixel could hold is that of the colour full where a weight is positive and empty
  // where it is not (in every pixel's arithmetic, so that none exceeds it).
  cv::Vec3b most_colour;
  for (int c = 0; c < 3; ++c) most_colour[c] = weights[c] > 0.0f ? 255 : 0;
  const double limit = max_peaks * (evidence_of(most_colour) - out.background);
  double lower_bound = 0.0;
  for (int index : blob.pixels) {
    lower_bound += std::max(0.0, evidence(index % bgr.cols, index / bgr.cols) - out.background);
    if (lower_bound > limit) return std::nullopt;
  }

  // Support: the blob grown by one pixel, so that the faint rim of the object counts.
  cv::Mat1b support(window.size(), uchar{0});
  for (int index : blob.pixels) {
    const int x = index % bgr.cols - window.x, y = index / bgr.cols - window.y;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int sx = x + dx, sy = y + dy;
        if (sx >= 0 && sy >= 0 && sx < support.cols && sy < support.rows) support(sy, sx) = 1;
      }
  }
  for (int y = 0; y < support.rows; ++y) {
    for (int x = 0; x < support.cols; ++x) {
      if (!support(y, x)) continue;
      const double w = evidence(window.x + x, window.y + y) - out.background;
      if (w <= 0.0) continue;
      out.pixels.push_back({static_cast<float>(window.x + x), static_cast<float>(window.y + y),
                            static_cast<float>(w)});
      if (w > out.peak) {
        out.peak = w;
        out.peak_bgr = bgr.at<cv::Vec3b>(window.y + y, window.x + x);
      }
    }
  }
  weighted_moments(out.pixels, out.mass, out.centroid, out.covariance);
  return out;
}

}  // namespace ballsight
