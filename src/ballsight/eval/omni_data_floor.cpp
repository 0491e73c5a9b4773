#include "ballsight/eval/omni_data_floor.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ballsight/core/angle.hpp"

namespace ballsight {

namespace {

// The ground distance at `radius_px` along one ray, from its samples (radius, distance): samples
// at one radius averaged, then linear between the two radii that bracket it, or through the two
// nearest beyond the end.
std::optional<double> along_ray(std::vector<std::pair<double, double>> ray, double radius_px) {
  std::sort(ray.begin(), ray.end());
  std::vector<std::pair<double, double>> radii;  // (radius, mean distance)
  for (std::size_t i = 0; i < ray.size();) {
    std::size_t j = i;
    double sum = 0.0;
    for (; j < ray.size() && ray[j].first == ray[i].first; ++j) sum += ray[j].second;
    radii.emplace_back(ray[i].first, sum / static_cast<double>(j - i));
    i = j;
  }
  if (radii.size() < 2) return std::nullopt;
  std::size_t upper = 1;  // the segment [upper - 1, upper] that holds (or is nearest) the radius
  while (upper + 1 < radii.size() && radii[upper].first < radius_px) ++upper;
  const auto [r0, d0] = radii[upper - 1];
  const auto [r1, d1] = radii[upper];
  return d0 + (d1 - d0) * (radius_px - r0) / (r1 - r0);
}

// The samples of `train` along the direction whose key is `key`.
std::vector<std::pair<double, double>> ray_of(std::span<const PolarSample> train, double key) {
  std::vector<std::pair<double, double>> ray;
  for (const PolarSample& s : train)
    if (direction_key(s.theta_deg) == key) ray.emplace_back(s.radius_px, s.distance_cm);
  return ray;
}

// A training direction beside the sample: its key and its angle from the sample (deg).
struct Side {
  double key = 0.0;
  double offset_deg = 0.0;
};

}  // namespace

std::optional<double> neighbour_distance_cm(std::span<const PolarSample> train,
                                            const PolarSample& sample, HeldOutSplit split) {
  const double own = direction_key(sample.theta_deg);
  if (split == HeldOutSplit::kDistance) return along_ray(ray_of(train, own), sample.radius_px);
  // The nearest training direction counter-clockwise (ahead) and clockwise (behind).
  std::optional<Side> ahead, behind;
  for (const double key : sample_directions(train)) {
    if (key == own) return along_ray(ray_of(train, key), sample.radius_px);
    const double offset = wrap_deg_180(key - sample.theta_deg);
    if (offset > 0.0 && (!ahead || offset < ahead->offset_deg)) ahead = Side{key, offset};
    if (offset <= 0.0 && (!behind || offset > behind->offset_deg)) behind = Side{key, offset};
  }
  const auto read = [&](const std::optional<Side>& side) -> std::optional<double> {
    return side ? along_ray(ray_of(train, side->key), sample.radius_px) : std::nullopt;
  };
  const std::optional<double> a = read(ahead), b = read(behind);
  if (a && b)
    return *b + (*a - *b) * -behind->offset_deg / (ahead->offset_deg - behind->offset_deg);
  return a ? a : b;
}

double held_out_error_cm(const std::optional<double>& predicted_cm, const PolarSample& sample,
                         std::size_t& unmapped) {
  if (!predicted_cm) {
    ++unmapped;
    return sample.distance_cm;
  }
  return std::abs(*predicted_cm - sample.distance_cm);
}

ErrorSummary neighbour_floor(std::span<const HeldOutFold> folds, HeldOutSplit split,
                             std::size_t& unmapped) {
  std::vector<double> errors;
  unmapped = 0;
  for (const HeldOutFold& fold : folds)
    for (const PolarSample& s : fold.test)
      errors.push_back(held_out_error_cm(neighbour_distance_cm(fold.train, s, split), s, unmapped));
  return summarize_errors(std::move(errors));
}

}  // namespace ballsight
