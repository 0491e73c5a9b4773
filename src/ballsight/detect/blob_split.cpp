#include "ballsight/detect/blob_split.hpp"

#include <algorithm>
#include <limits>

namespace ballsight {

namespace {

double squared_distance(const EvidencePixel& p, const Vec2& c) {
  const double dx = p.x - c.x(), dy = p.y - c.y();
  return dx * dx + dy * dy;
}

// Farthest-point start: the strong pixel farthest from the centroid, then repeatedly the strong
// pixel farthest from every centre chosen so far.
std::vector<Vec2> initial_centres(const std::vector<EvidencePixel>& pixels, int count,
                                  const Vec2& centroid, double strong_weight) {
  std::vector<Vec2> centres;
  std::vector<double> nearest(pixels.size(), std::numeric_limits<double>::max());
  Vec2 from = centroid;
  for (int k = 0; k < count; ++k) {
    double best = -1.0;
    Vec2 pick = centroid;
    for (size_t i = 0; i < pixels.size(); ++i) {
      if (pixels[i].weight < strong_weight) continue;
      nearest[i] = std::min(nearest[i], k == 0 ? squared_distance(pixels[i], from)
                                               : squared_distance(pixels[i], centres.back()));
      if (nearest[i] > best) {
        best = nearest[i];
        pick = Vec2(pixels[i].x, pixels[i].y);
      }
    }
    if (k == 0) std::fill(nearest.begin(), nearest.end(), std::numeric_limits<double>::max());
    centres.push_back(pick);
  }
  return centres;
}

}  // namespace

std::vector<BlobPart> split_blob(const std::vector<EvidencePixel>& pixels, int count,
                                 int iterations) {
  count = std::min<int>(count, static_cast<int>(pixels.size()));
  if (count <= 0) return {};
  double mass = 0.0, peak = 0.0;
  Vec2 centroid;
  Eigen::Matrix2d covariance;
  weighted_moments(pixels, mass, centroid, covariance);
  for (const EvidencePixel& p : pixels) peak = std::max<double>(peak, p.weight);
  std::vector<Vec2> centres = initial_centres(pixels, count, centroid, 0.3 * peak);

  std::vector<int> label(pixels.size(), 0);
  for (int iteration = 0; iteration < iterations; ++iteration) {
    bool changed = false;
    for (size_t i = 0; i < pixels.size(); ++i) {
      int best = 0;
      double best_d = std::numeric_limits<double>::max();
      for (int k = 0; k < count; ++k) {
        const double d = squared_distance(pixels[i], centres[static_cast<size_t>(k)]);
        if (d < best_d) best_d = d, best = k;
      }
      changed |= label[i] != best;
      label[i] = best;
    }
    std::vector<Vec2> sum(static_cast<size_t>(count), Vec2::Zero());
    std::vector<double> weight(static_cast<size_t>(count), 0.0);
    for (size_t i = 0; i < pixels.size(); ++i) {
      const auto k = static_cast<size_t>(label[i]);
      sum[k] += pixels[i].weight * Vec2(pixels[i].x, pixels[i].y);
      weight[k] += pixels[i].weight;
    }
    for (size_t k = 0; k < centres.size(); ++k)
      if (weight[k] > 0.0) centres[k] = sum[k] / weight[k];
    if (!changed && iteration > 0) break;
  }

  std::vector<BlobPart> parts(static_cast<size_t>(count));
  for (size_t i = 0; i < pixels.size(); ++i)
    parts[static_cast<size_t>(label[i])].pixels.push_back(pixels[i]);
  for (BlobPart& part : parts)
    weighted_moments(part.pixels, part.mass, part.centroid, part.covariance);
  std::erase_if(parts, [](const BlobPart& part) { return part.mass <= 0.0; });
  return parts;
}

}  // namespace ballsight
