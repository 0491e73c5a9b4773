// fit_ballsight_model: the physical model, and the radius correction chosen by cross-validation.
// Every candidate (the physical model alone, the correction at each smoothing of the grid and,
// given enough distances, at finer segmentations) is scored by its held-out radius error (pixels,
// where click noise is symmetric) on held-out directions and on held-out whole distances of the
// samples (calib/held_out_folds.hpp; the two splits weigh alike), the physical model refitted on
// each fold's training part. The simplest candidate within one standard error of the best is
// fitted to all samples; the correction must keep the model monotone over the physical model's
// valid range, else the next is taken.

#include <algorithm>
#include <cmath>
#include <vector>

#include "ballsight/calib/ballsight_model.hpp"
#include "ballsight/calib/held_out_folds.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

constexpr double kSmoothingGrid[] = {0.01, 0.1, 1.0, 10.0, 100.0};
// The correction's segments along the radius: 6 for a smooth correction, 12 and 24 for a mirror
// whose profile bends sharply (a compound mirror's knee; on the simulated table profile, found
// markers, 6 leave the mapping 7.4 cm off on held-out points). A finer correction is a candidate
// only where the training part of every distance fold (one distance fewer) still holds a
// distance for every two of its segments: between a few rings (5 on the real ring sets) its
// freedom only follows the noise of the held-out folds.
constexpr int kRadiusSegments[] = {6, 12, 24};
constexpr std::size_t kMinFoldSamples = 8;
constexpr std::size_t kMinFoldDistances = 3;
constexpr std::size_t kMaxFolds = 3;  // per split
constexpr double kReachPx = 50.0;     // a held-out sample's radius error at most

// The radius at which `model`, along image angle theta, reads `distance_cm`: a walk
// from `start_px` in 0.5 px steps towards it, then false position within the step. nullopt when it
// is not reached within `reach_px` (beyond the horizon, or a model far off).
std::optional<double> radius_reading(const OmniGroundModel& model, double theta_deg,
                                     double distance_cm, double start_px, double reach_px) {
  const auto reads = [&](double r) { return model.predict(theta_deg, r).distance_cm; };
  double a = start_px;
  double da = reads(a);
  if (!std::isfinite(da)) return std::nullopt;
  const double step = da < distance_cm ? 0.5 : -0.5;
  for (double walked = 0.0; walked < reach_px; walked += 0.5) {
    const double b = a + step;
    if (b <= 0.0) return std::nullopt;
    const double db = reads(b);
    if (!std::isfinite(db)) return std::nullopt;
    if ((db - distance_cm) * (da - distance_cm) <= 0.0) {
      // Illinois false position within the bracket: a few readings instead of 30 halvings.
      double x0 = a, f0 = da - distance_cm, x1 = b, f1 = db - distance_cm, x = b;
      for (int i = 0; i < 60 && f1 != 0.0; ++i) {  // f0 and f1 keep opposite signs
        const double next = (x0 * f1 - x1 * f0) / (f1 - f0);
        if (std::abs(next - x) < 1e-9) return next;
        x = next;
        const double fx = reads(x) - distance_cm;
        if (!std::isfinite(fx)) return std::nullopt;
        if (fx * f1 < 0.0) {
          x0 = x1, f0 = f1;
        } else {
          f0 *= 0.5;
        }
        x1 = x, f1 = fx;
      }
      return x1;
    }
    a = b;
    da = db;
  }
  return std::nullopt;
}

std::vector<WarpTarget> warp_targets(const BallsightGroundModel& physical,
                                     std::span<const PolarSample> samples) {
  const RadiusRange& range = physical.domain().valid_radius;
  const double reach = std::max(range.max_px - range.min_px, 10.0);
  std::vector<WarpTarget> targets;
  for (const PolarSample& s : samples) {
    if (const auto r = radius_reading(physical, s.theta_deg, s.distance_cm, s.radius_px, reach)) {
      targets.push_back({s.theta_deg, s.radius_px, *r - s.radius_px});
    }
  }
  return targets;
}

// A candidate: no correction (nullopt) or the correction at these smoothings.
struct Candidate {
  std::optional<RadialWarpFitOptions> warp;
};

std::vector<Candidate> candidates(std::span<const PolarSample> samples) {
  std::vector<Candidate> all{{std::nullopt}};
  // Gaps between the distances of a distance fold's training part.
  const auto gaps = static_cast<int>(sample_distances(samples).size()) - 2;
  for (const int segments : kRadiusSegments) {
    if (segments != kRadiusSegments[0] && segments > 2 * gaps) break;
    for (const double theta : kSmoothingGrid) {
      for (const double radius : kSmoothingGrid) {
        RadialWarpFitOptions options;
        options.radius_segments = segments;
        options.theta_smoothing = theta;
        options.radius_smoothing = radius;
        all.push_back({options});
      }
    }
  }
  return all;
}

// The physical model with the candidate's correction, fitted to `targets` (warp_targets of the
// physical model: they do not depend on the candidate).
BallsightGroundModel with_candidate(const BallsightGroundModel& physical,
                                    std::span<const WarpTarget> targets,
                                    const Candidate& candidate) {
  if (!candidate.warp || targets.empty()) return physical;
  return {physical.params(), physical.domain(), fit_radial_warp(targets, *candidate.warp)};
}

bool fittable(std::span<const PolarSample> samples) {
  return samples.size() >= kMinFoldSamples && sample_distances(samples).size() >= kMinFoldDistances;
}

// The held-out radius errors of every candidate, per split and held-out sample.
using SplitErrors = std::vector<std::vector<double>>;  // [candidate][sample]

std::vector<SplitErrors> cross_validated_errors(std::span<const PolarSample> samples,
                                                const OmniImage& image,
                                                const BallsightFitOptions& options,
                                                const std::vector<Candidate>& all) {
  std::vector<SplitErrors> splits;
  for (const HeldOutSplit split : {HeldOutSplit::kDirections, HeldOutSplit::kDistance}) {
    SplitErrors errors(all.size());
    for (const HeldOutFold& fold : spread_folds(held_out_folds(samples, split), kMaxFolds)) {
      if (!fittable(fold.train) || fold.test.empty()) continue;
      std::optional<BallsightGroundModel> physical;
      try {
        physical = fit_physical_ballsight_model(fold.train, image, options);
      } catch (const InputError&) {
        continue;  // this fold's training part has no monotone physical fit
      }
      const std::vector<WarpTarget> targets = warp_targets(*physical, fold.train);
      for (std::size_t c = 0; c < all.size(); ++c) {
        const BallsightGroundModel model = with_candidate(*physical, targets, all[c]);
        for (const PolarSample& s : fold.test) {
          const auto r = radius_reading(model, s.theta_deg, s.distance_cm, s.radius_px, kReachPx);
          errors[c].push_back(r ? std::abs(*r - s.radius_px) : kReachPx);
        }
      }
    }
    if (!errors[0].empty()) splits.push_back(std::move(errors));
  }
  return splits;
}

// How much candidate `c`'s error exceeds `reference`'s, and the standard error of that excess
// (paired over the held-out samples), the splits' means summed.
std::pair<double, double> excess_error(const std::vector<SplitErrors>& splits, std::size_t c,
                                       std::size_t reference) {
  double excess = 0.0, variance = 0.0;
  for (const SplitErrors& errors : splits) {
    const std::size_t n = errors[c].size();
    double sum = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double d = errors[c][i] - errors[reference][i];
      sum += d;
      squares += d * d;
    }
    const double count = static_cast<double>(n);
    const double mean = sum / count;
    excess += mean;
    if (n > 1) variance += std::max(squares - count * mean * mean, 0.0) / (count - 1.0) / count;
  }
  return {excess, std::sqrt(variance)};
}

// Candidates from the simplest: the physical model alone, then the correction from the fewest
// segments and, among equals, the smoothest.
std::vector<std::size_t> simplest_first(const std::vector<Candidate>& all) {
  std::vector<std::size_t> order(all.size());
  for (std::size_t c = 0; c < all.size(); ++c) order[c] = c;
  const auto segments = [&](std::size_t c) {
    return all[c].warp ? all[c].warp->radius_segments : 0;
  };
  const auto smoothing = [&](std::size_t c) {
    return all[c].warp ? all[c].warp->theta_smoothing + all[c].warp->radius_smoothing : INFINITY;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return segments(a) != segments(b) ? segments(a) < segments(b) : smoothing(a) > smoothing(b);
  });
  return order;
}

}  // namespace

BallsightGroundModel fit_ballsight_model(std::span<const PolarSample> samples,
                                         const OmniImage& image,
                                         const BallsightFitOptions& options) {
  const BallsightGroundModel physical = fit_physical_ballsight_model(samples, image, options);
  if (!options.radial_warp) return physical;
  const std::vector<Candidate> all = candidates(samples);
  const std::vector<SplitErrors> splits = cross_validated_errors(samples, image, options, all);
  if (splits.empty()) return physical;
  // The one-standard-error rule: the simplest candidate whose error is within one standard
  // error of the best one's. On a mirror of the physical family the correction would fit click
  // noise; the rule keeps it out.
  std::size_t best = 0;
  for (std::size_t c = 1; c < all.size(); ++c) {
    if (excess_error(splits, c, best).first < 0.0) best = c;
  }
  const RadiusRange& range = physical.domain().valid_radius;
  const std::vector<WarpTarget> targets = warp_targets(physical, samples);
  for (const std::size_t c : simplest_first(all)) {
    const auto [excess, standard_error] = excess_error(splits, c, best);
    if (excess > standard_error) continue;
    if (!all[c].warp) return physical;
    const BallsightGroundModel model = with_candidate(physical, targets, all[c]);
    const RadiusRange monotone = monotone_radius_range(model, range);
    if (monotone.min_px <= range.min_px && monotone.max_px >= range.max_px) return model;
  }
  return physical;
}

}  // namespace ballsight
