#pragma once
// ballsight's omni mapping: a central catadioptric floor model (catadioptric_floor.hpp) fitted
// to the samples by robust non-linear least squares (Ceres; Huber, then Cauchy), read through a
// smooth correction of the image radius (radial_warp.hpp) where cross-validation over held-out
// directions and whole distances says the mirror is not of the physical model's family. It maps
// direction as well as distance (a tilted mirror bends bearings), is checked strictly monotone
// in radius along every ray of its valid range, and flags queries outside that range.

#include <optional>
#include <span>

#include "ballsight/calib/catadioptric_floor.hpp"
#include "ballsight/calib/omni_ground_model.hpp"
#include "ballsight/calib/radial_warp.hpp"

namespace ballsight {

struct BallsightFitOptions {
  double huber_px = 2.0;            // first, convex pass: Huber loss width (pixel-like residuals)
  double min_cauchy_px = 0.5;       // second pass: Cauchy scale, 2.5 robust sigma, at least this
  double prior_center_px = 20.0;    // weak prior: principal point near the image centre
  double prior_rotation_deg = 5.0;  // weak prior: mount rotation near the ideal
  double prior_distortion = 0.1;    // weak prior: distortion terms near zero
  int max_iterations = 200;         // per pass
  double range_margin_fraction = 0.03;  // valid range beyond the sample radii, of their span
  int distortion_terms = 0;  // radial distortion terms fitted (0 to 3; catadioptric_floor.hpp)
  /// The effective viewpoint's height above the floor as measured on the robot, if it was, and
  /// the measurement's standard deviation: a prior the fit weighs against the samples.
  std::optional<double> viewpoint_height_cm;
  double viewpoint_height_sigma_cm = 0.5;
  /// Whether the radius correction may be chosen: cross-validation then picks between the
  /// physical model alone and the correction with each smoothing of the grid.
  bool radial_warp = true;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class BallsightGroundModel final : public OmniGroundModel {
 public:
  BallsightGroundModel(const CatadioptricFloorParams& params, const OmniModelDomain& domain,
                       std::optional<RadialWarp> warp = std::nullopt);

  static BallsightGroundModel from_parameters_json(const nlohmann::json& parameters,
                                                   const OmniModelDomain& domain);

  std::string_view name() const override { return "ballsight"; }
  const OmniModelDomain& domain() const override { return domain_; }
  GroundPrediction predict(double theta_deg, double radius_px) const override;
  nlohmann::json parameters_json() const override;
  std::optional<double> viewpoint_height_cm() const override { return params_.height_cm; }

  /// The physical model's parameters (without the radius correction).
  const CatadioptricFloorParams& params() const { return params_; }
  const std::optional<RadialWarp>& warp() const { return warp_; }

 private:
  CatadioptricFloorParams params_;
  OmniModelDomain domain_;
  std::optional<RadialWarp> warp_;
};

/// Fits the model (ballsight_model_selection.cpp): the physical model, then the radius
/// correction if it lowers the cross-validated error. Samples without bearing constrain distance
/// only (the yaw then stays at its prior, zero). Throws InputError with fewer than 8 samples or
/// 3 distinct distances.
BallsightGroundModel fit_ballsight_model(std::span<const PolarSample> samples,
                                         const OmniImage& image,
                                         const BallsightFitOptions& options = {});

/// The physical model alone, fitted to the samples (same errors as fit_ballsight_model).
BallsightGroundModel fit_physical_ballsight_model(std::span<const PolarSample> samples,
                                                  const OmniImage& image,
                                                  const BallsightFitOptions& options = {});

/// The largest sub-range of `range` (containing the middle of it) on which the model's distance
/// is finite and strictly increasing along each of `rays` image rays, probed every `step_px`.
RadiusRange monotone_radius_range(const OmniGroundModel& model, const RadiusRange& range,
                                  int rays = 360, double step_px = 0.25);

}  // namespace ballsight
