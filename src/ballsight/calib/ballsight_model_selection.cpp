// fit_ballsight_model: the physical model, and the radius correction chosen by cross-validation.
// Every candidate (the physical model alone, the correction at each smoothing of the grid) is
// scored by its mean ground-distance error on held-out directions and on held-out whole
// distances of the samples (calib/held_out_folds.hpp; the two splits weigh alike), the physical
// model refitted on each fold's training part; the best is fitted to all samples. The correction
// must keep the model monotone over the physical model's valid range, else the next smoother
// candidate is taken.

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "ballsight/calib/ballsight_model.hpp"
#include "ballsight/calib/held_out_folds.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

constexpr double kSmoothingGrid[] = {0.01, 0.1, 1.0, 10.0, 100.0};
constexpr std::size_t kMinFoldSamples = 8;
constexpr std::size_t kMinFoldDistances = 3;
constexpr std::size_t kMaxFolds = 3;  // per split
constexpr double kReachPx = 50.0;     // a held-out sample's radius error at most
constexpr double kSureGain = 0.0;     // standard errors

// The radius at which the physical model, along image angle theta, reads `distance_cm`: a walk
// from `start_px` in 0.5 px steps towards it, then bisection. nullopt when it is not reached
// within `reach_px` (beyond the horizon, or a model far off).
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
      double lo = std::min(a, b), hi = std::max(a, b);
      for (int i = 0; i < 30; ++i) {
        const double mid = 0.5 * (lo + hi);
        (reads(mid) < distance_cm ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
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

std::vector<Candidate> candidates() {
  std::vector<Candidate> all{{std::nullopt}};
  for (const double theta : kSmoothingGrid) {
    for (const double radius : kSmoothingGrid) {
      RadialWarpFitOptions options;
      options.theta_smoothing = theta;
      options.radius_smoothing = radius;
      all.push_back({options});
    }
  }
  return all;
}

BallsightGroundModel with_candidate(const BallsightGroundModel& physical,
                                    std::span<const PolarSample> samples,
                                    const Candidate& candidate) {
  if (!candidate.warp) return physical;
  const std::vector<WarpTarget> targets = warp_targets(physical, samples);
  if (targets.empty()) return physical;
  return {physical.params(), physical.domain(), fit_radial_warp(targets, *candidate.warp)};
}

bool fittable(std::span<const PolarSample> samples) {
  return samples.size() >= kMinFoldSamples && sample_distances(samples).size() >= kMinFoldDistances;
}

// At most `count` of the folds, evenly spread (the nearest, middle and farthest held-out
// distance of many): the cost stays that of a few fits.
std::vector<HeldOutFold> spread_folds(std::vector<HeldOutFold> folds, std::size_t count) {
  if (folds.size() <= count) return folds;
  std::vector<HeldOutFold> kept;
  for (std::size_t k = 0; k < count; ++k) {
    kept.push_back(std::move(folds[k * (folds.size() - 1) / (count - 1)]));
  }
  return kept;
}

// A candidate's cross-validated score: its mean held-out distance error (the two splits'
// means averaged) and how much and how surely it beats the physical model alone.
struct Score {
  double error_cm = 0.0;
  double gain_cm = 0.0;     // the physical model's error minus this one's
  double gain_se_cm = 0.0;  // the standard error of that gain (paired over held-out samples)
};

// Every candidate's score (all[0] is the physical model alone); empty when no fold can be
// fitted.
std::vector<Score> cross_validated_scores(std::span<const PolarSample> samples,
                                          const OmniImage& image,
                                          const BallsightFitOptions& options,
                                          const std::vector<Candidate>& all) {
  std::vector<Score> scores(all.size());
  int splits = 0;
  for (const HeldOutSplit split : {HeldOutSplit::kDirections, HeldOutSplit::kDistance}) {
    std::vector<std::vector<double>> errors(all.size());  // per candidate, per held-out sample
    for (const HeldOutFold& fold : spread_folds(held_out_folds(samples, split), kMaxFolds)) {
      if (!fittable(fold.train) || fold.test.empty()) continue;
      std::optional<BallsightGroundModel> physical;
      try {
        physical = fit_physical_ballsight_model(fold.train, image, options);
      } catch (const InputError&) {
        continue;  // this fold's training part has no monotone physical fit
      }
      for (std::size_t c = 0; c < all.size(); ++c) {
        const BallsightGroundModel model = with_candidate(*physical, fold.train, all[c]);
        for (const PolarSample& s : fold.test) {
          const auto r = radius_reading(model, s.theta_deg, s.distance_cm, s.radius_px, kReachPx);
          errors[c].push_back(r ? std::abs(*r - s.radius_px) : kReachPx);
        }
      }
    }
    const std::size_t n = errors[0].size();
    if (n == 0) continue;
    ++splits;
    for (std::size_t c = 0; c < all.size(); ++c) {
      double sum = 0.0, gain = 0.0, gain_squares = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        sum += errors[c][i];
        const double g = errors[0][i] - errors[c][i];
        gain += g;
        gain_squares += g * g;
      }
      const double mean_gain = gain / static_cast<double>(n);
      const double variance =
          n > 1 ? (gain_squares - static_cast<double>(n) * mean_gain * mean_gain) /
                      static_cast<double>(n - 1)
                : 0.0;
      scores[c].error_cm += sum / static_cast<double>(n);
      scores[c].gain_cm += mean_gain;
      scores[c].gain_se_cm += std::max(variance, 0.0) / static_cast<double>(n);  // variance, yet
    }
  }
  if (splits == 0) return {};
  for (Score& score : scores) score.gain_se_cm = std::sqrt(score.gain_se_cm);
  return scores;
}

}  // namespace

BallsightGroundModel fit_ballsight_model(std::span<const PolarSample> samples,
                                         const OmniImage& image,
                                         const BallsightFitOptions& options) {
  const BallsightGroundModel physical = fit_physical_ballsight_model(samples, image, options);
  if (!options.radial_warp) return physical;
  const std::vector<Candidate> all = candidates();
  const std::vector<Score> scores = cross_validated_scores(samples, image, options, all);
  if (scores.empty()) return physical;
  // The correction only where it beats the physical model surely (its gain at least twice its
  // standard error): on a mirror of the physical family it would fit click noise.
  std::multimap<double, std::size_t> ranked;
  for (std::size_t c = 1; c < all.size(); ++c) {
    if (scores[c].gain_cm > kSureGain * scores[c].gain_se_cm) ranked.emplace(scores[c].error_cm, c);
  }
  const RadiusRange& range = physical.domain().valid_radius;
  for (const auto& [error, c] : ranked) {
    const BallsightGroundModel model = with_candidate(physical, samples, all[c]);
    const RadiusRange monotone = monotone_radius_range(model, range);
    if (monotone.min_px <= range.min_px && monotone.max_px >= range.max_px) return model;
  }
  return physical;
}

}  // namespace ballsight
