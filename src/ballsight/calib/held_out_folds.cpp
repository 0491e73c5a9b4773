#include "ballsight/calib/held_out_folds.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace ballsight {

double direction_key(double theta_deg) {
  return std::round(theta_deg * 1000.0) / 1000.0;
}

std::string_view held_out_split_name(HeldOutSplit split) {
  return split == HeldOutSplit::kDirections ? "directions" : "distance";
}

std::vector<double> sample_directions(std::span<const PolarSample> samples) {
  std::set<double> directions;
  for (const PolarSample& s : samples) directions.insert(direction_key(s.theta_deg));
  return {directions.begin(), directions.end()};
}

std::vector<double> sample_distances(std::span<const PolarSample> samples) {
  std::set<double> distances;
  for (const PolarSample& s : samples) distances.insert(s.distance_cm);
  return {distances.begin(), distances.end()};
}

std::vector<HeldOutFold> held_out_folds(std::span<const PolarSample> samples, HeldOutSplit split) {
  std::vector<HeldOutFold> folds;
  if (split == HeldOutSplit::kDirections) {
    const std::vector<double> directions = sample_directions(samples);
    if (directions.size() < 2) return folds;
    for (std::size_t fold = 0; fold < 2; ++fold) {
      HeldOutFold& f = folds.emplace_back();
      for (const PolarSample& s : samples) {
        const auto index =
            std::lower_bound(directions.begin(), directions.end(), direction_key(s.theta_deg)) -
            directions.begin();
        (static_cast<std::size_t>(index) % 2 == fold ? f.test : f.train).push_back(s);
      }
    }
    return folds;
  }
  const std::vector<double> distances = sample_distances(samples);
  for (std::size_t i = 1; i + 1 < distances.size(); ++i) {
    HeldOutFold& f = folds.emplace_back();
    for (const PolarSample& s : samples) {
      (s.distance_cm == distances[i] ? f.test : f.train).push_back(s);
    }
  }
  return folds;
}

std::vector<HeldOutFold> spread_folds(std::vector<HeldOutFold> folds, std::size_t count) {
  if (folds.size() <= count) return folds;
  std::vector<HeldOutFold> kept;
  for (std::size_t k = 0; k < count; ++k) {
    kept.push_back(std::move(folds[k * (folds.size() - 1) / (count - 1)]));
  }
  return kept;
}

}  // namespace ballsight
