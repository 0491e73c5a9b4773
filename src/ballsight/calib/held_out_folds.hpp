#pragma once
// Cross-validation folds of omni calibration samples, by the two ways a calibration must
// generalise. Directions: every other direction (image angle) is held out, two folds. Whole
// distance: each distance but the nearest and the farthest is held out in turn, every sample at
// it (interpolation along the ray).

#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "ballsight/calib/polar_sample.hpp"

namespace ballsight {

enum class HeldOutSplit { kDirections, kDistance };

/// "directions", "distance".
std::string_view held_out_split_name(HeldOutSplit split);

struct HeldOutFold {
  std::vector<PolarSample> train;
  std::vector<PolarSample> test;
};

/// The folds of `split`: none for directions with one direction, none for distance with fewer
/// than three distances.
std::vector<HeldOutFold> held_out_folds(std::span<const PolarSample> samples, HeldOutSplit split);

/// At most `count` (>= 2) of the folds, evenly spread: of many held-out distances the nearest,
/// the farthest and evenly between.
std::vector<HeldOutFold> spread_folds(std::vector<HeldOutFold> folds, std::size_t count);

/// A direction as the folds tell directions apart: the image angle rounded to 0.001 deg.
double direction_key(double theta_deg);

/// The distinct directions (direction_key) and distances, sorted.
std::vector<double> sample_directions(std::span<const PolarSample> samples);
std::vector<double> sample_distances(std::span<const PolarSample> samples);

}  // namespace ballsight
