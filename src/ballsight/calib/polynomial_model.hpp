#pragma once
// The omnivision paper's baseline (Eq. 1, Algorithm 1): one polynomial in pixel radius gives the
// ground distance in every direction; the direction is the image direction.

#include <cmath>
#include <span>
#include <vector>

#include "ballsight/calib/omni_ground_model.hpp"

namespace ballsight {

struct PolynomialFitOptions {
  int degree = 6;  // as the paper team's robots use

  /// Throws InputError unless degree is in [1, 12].
  void validate() const;
};

/// d(r) = sum_k a_k x^k with x = (r - offset_px) / scale_px: the scaled radius keeps the least
/// squares well conditioned.
struct RadialPolynomial {
  std::vector<double> coefficients;  // a_0 .. a_n
  double offset_px = 0.0;
  double scale_px = 1.0;

  double operator()(double radius_px) const {
    const double x = (radius_px - offset_px) / scale_px;
    double value = 0.0;
    for (auto it = coefficients.rbegin(); it != coefficients.rend(); ++it) value = value * x + *it;
    return value;
  }
};

class PolynomialGroundModel final : public OmniGroundModel {
 public:
  PolynomialGroundModel(RadialPolynomial polynomial, const OmniModelDomain& domain);

  /// Reads parameters_json(); throws InputError naming the field.
  static PolynomialGroundModel from_parameters_json(const nlohmann::json& parameters,
                                                    const OmniModelDomain& domain);

  std::string_view name() const override { return "poly"; }
  const OmniModelDomain& domain() const override { return domain_; }
  GroundPrediction predict(double theta_deg, double radius_px) const override;
  nlohmann::json parameters_json() const override;

  const RadialPolynomial& polynomial() const { return polynomial_; }

  /// The run-time hot path of Algorithm 1: pixel -> robot-frame ground point (cm), no range
  /// check. The bearing is the image angle - 90 deg, so cos/sin of it are (dy, -dx) / r and
  /// atan2, cos and sin cancel out (same result, no trigonometry).
  Vec2 convert(const Vec2& pixel) const {
    const double dx = pixel.x() - domain_.image.center_px.x();
    const double dy = domain_.image.center_px.y() - pixel.y();
    const double r = std::sqrt(dx * dx + dy * dy);
    const double per_px = r > 0.0 ? polynomial_(r) / r : 0.0;
    return {per_px * dy, -per_px * dx};
  }

 private:
  RadialPolynomial polynomial_;
  OmniModelDomain domain_;
};

/// Least squares of distance_cm on radius_px (Eigen column-pivoting QR on the scaled radius).
/// Throws InputError when there are fewer distinct radii than coefficients.
PolynomialGroundModel fit_polynomial_model(std::span<const PolarSample> samples,
                                           const OmniImage& image,
                                           const PolynomialFitOptions& options = {});

}  // namespace ballsight
