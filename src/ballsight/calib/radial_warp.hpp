#pragma once
// A smooth correction of the image radius, w(theta, r) in pixels: ballsight's omni model reads
// its physical floor model at r + w(theta, r), so that a mirror outside the physical model's
// family (spherical, conical, compound, manufactured with ripples) is still mapped right. w is a
// tensor-product cubic B-spline, periodic in the image angle and clamped at the ends of its
// radius span (constant beyond), fitted by penalised least squares (P-splines: second
// differences along both axes, a ridge towards zero, so the physical model is the prior) with a
// Huber loss against a few mislabelled samples.

#include <nlohmann/json_fwd.hpp>
#include <span>
#include <vector>

#include "ballsight/calib/omni_ground_model.hpp"

namespace ballsight {

/// One sample as the warp sees it: at image angle theta the sample's radius must move by
/// `shift_px` for the physical model to read the sample's distance.
struct WarpTarget {
  double theta_deg = 0.0;
  double radius_px = 0.0;
  double shift_px = 0.0;
};

struct RadialWarpFitOptions {
  int theta_segments = 8;        // B-spline segments around the circle (45 deg each)
  int radius_segments = 6;       // over the targets' radius span
  double theta_smoothing = 1.0;  // second-difference penalties, relative to the data's weight
  double radius_smoothing = 1.0;
  double huber_px = 1.0;  // at least; else 2 robust sigmas of the residuals
  int reweighting_passes = 3;
};

class RadialWarp {
 public:
  RadialWarp(int theta_segments, RadiusRange span, int radius_segments,
             std::vector<double> coefficients);

  /// The radius shift at (theta, r), pixels.
  double operator()(double theta_deg, double radius_px) const;

  nlohmann::json to_json() const;
  /// Reads to_json(); throws InputError naming the field under `where`.
  static RadialWarp from_json(const nlohmann::json& value, const std::string& where);

 private:
  int theta_segments_;
  RadiusRange span_;
  int radius_segments_;
  std::vector<double> coefficients_;  // theta-major: index theta * (radius_segments + 3) + radius
};

/// Fits the warp to the targets. Throws InputError for an empty set or bad options.
RadialWarp fit_radial_warp(std::span<const WarpTarget> targets,
                           const RadialWarpFitOptions& options = {});

}  // namespace ballsight
