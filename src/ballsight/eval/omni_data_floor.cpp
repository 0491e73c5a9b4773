#include "ballsight/eval/omni_data_floor.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ballsight/core/angle.hpp"

namespace ballsight {

namespace {

constexpr double kSameDirectionDeg = 1e-3;  // as sample_directions() tells directions apart

// The ground distance at `radius_px` along one direction, from its samples (radius, distance):
// linear between the two that bracket it, or through the two nearest beyond the end.
std::optional<double> along_ray(std::vector<std::pair<double, double>> ray, double radius_px) {
  if (ray.size() < 2) return std::nullopt;
  std::sort(ray.begin(), ray.end());
  std::size_t upper = 1;  // the segment [upper - 1, upper] that holds (or is nearest) the radius
  while (upper + 1 < ray.size() && ray[upper].first < radius_px) ++upper;
  const auto [r0, d0] = ray[upper - 1];
  const auto [r1, d1] = ray[upper];
  if (r1 == r0) return 0.5 * (d0 + d1);
  return d0 + (d1 - d0) * (radius_px - r0) / (r1 - r0);
}

// The samples of `train` along the direction `theta_deg`.
std::vector<std::pair<double, double>> ray_of(std::span<const PolarSample> train,
                                              double theta_deg) {
  std::vector<std::pair<double, double>> ray;
  for (const PolarSample& s : train)
    if (std::abs(wrap_deg_180(s.theta_deg - theta_deg)) < kSameDirectionDeg)
      ray.emplace_back(s.radius_px, s.distance_cm);
  return ray;
}

}  // namespace

std::optional<double> neighbour_distance_cm(std::span<const PolarSample> train,
                                            const PolarSample& sample, HeldOutSplit split) {
  if (split == HeldOutSplit::kDistance)
    return along_ray(ray_of(train, sample.theta_deg), sample.radius_px);
  // The nearest training direction counter-clockwise (ahead) and clockwise (behind).
  std::optional<double> ahead, behind;  // their angular offsets from the sample, deg
  for (const double theta : sample_directions(train)) {
    const double offset = wrap_deg_180(theta - sample.theta_deg);
    if (std::abs(offset) < kSameDirectionDeg)
      return along_ray(ray_of(train, theta), sample.radius_px);
    if (offset > 0.0 && (!ahead || offset < *ahead)) ahead = offset;
    if (offset < 0.0 && (!behind || offset > *behind)) behind = offset;
  }
  const auto read = [&](const std::optional<double>& offset) -> std::optional<double> {
    if (!offset) return std::nullopt;
    return along_ray(ray_of(train, sample.theta_deg + *offset), sample.radius_px);
  };
  const std::optional<double> a = read(ahead), b = read(behind);
  if (a && b) return *b + (*a - *b) * (-*behind) / (*ahead - *behind);
  return a ? a : b;
}

ErrorSummary neighbour_floor(std::span<const HeldOutFold> folds, HeldOutSplit split,
                             std::size_t& unmapped) {
  std::vector<double> errors;
  unmapped = 0;
  for (const HeldOutFold& fold : folds) {
    for (const PolarSample& s : fold.test) {
      const std::optional<double> d = neighbour_distance_cm(fold.train, s, split);
      if (!d) ++unmapped;
      errors.push_back(d ? std::abs(*d - s.distance_cm) : s.distance_cm);
    }
  }
  return summarize_errors(std::move(errors));
}

}  // namespace ballsight
