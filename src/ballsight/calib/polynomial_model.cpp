#include "ballsight/calib/polynomial_model.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"

namespace ballsight {

void PolynomialFitOptions::validate() const {
  require(degree >= 1 && degree <= 12, "poly degree",
          "expected an integer in [1, 12], got " + std::to_string(degree));
}

PolynomialGroundModel::PolynomialGroundModel(RadialPolynomial polynomial,
                                             const OmniModelDomain& domain)
    : polynomial_(std::move(polynomial)), domain_(domain) {}

GroundPrediction PolynomialGroundModel::predict(double theta_deg, double radius_px) const {
  return {polynomial_(radius_px), std::nullopt, domain_.contains(theta_deg, radius_px)};
}

nlohmann::json PolynomialGroundModel::parameters_json() const {
  return {{"degree", polynomial_.coefficients.size() - 1},
          {"radius_offset_px", polynomial_.offset_px},
          {"radius_scale_px", polynomial_.scale_px},
          {"coefficients", polynomial_.coefficients}};
}

PolynomialGroundModel PolynomialGroundModel::from_parameters_json(const nlohmann::json& parameters,
                                                                  const OmniModelDomain& domain) {
  const std::string where = "parameters";
  const int degree = json_int(parameters, "degree", where, 1, 12);
  RadialPolynomial polynomial;
  polynomial.offset_px = json_number(parameters, "radius_offset_px", where);
  polynomial.scale_px = json_number(parameters, "radius_scale_px", where);
  require(polynomial.scale_px > 0.0, where + ".radius_scale_px", "expected a positive number");
  polynomial.coefficients =
      json_numbers(parameters, "coefficients", where, static_cast<std::size_t>(degree) + 1);
  return {std::move(polynomial), domain};
}

PolynomialGroundModel fit_polynomial_model(std::span<const PolarSample> samples,
                                           const OmniImage& image,
                                           const PolynomialFitOptions& options) {
  options.validate();
  image.validate();
  const auto terms = static_cast<std::size_t>(options.degree) + 1;
  std::set<double> radii;
  for (const PolarSample& s : samples) radii.insert(s.radius_px);
  require(radii.size() >= terms, "samples",
          "a degree " + std::to_string(options.degree) + " polynomial needs at least " +
              std::to_string(terms) + " samples with distinct radii, got " +
              std::to_string(radii.size()));

  RadialPolynomial polynomial;
  polynomial.offset_px = 0.5 * (*radii.begin() + *radii.rbegin());
  polynomial.scale_px = 0.5 * (*radii.rbegin() - *radii.begin());
  const auto rows = static_cast<Eigen::Index>(samples.size());
  Eigen::MatrixXd vandermonde(rows, static_cast<Eigen::Index>(terms));
  Eigen::VectorXd distances(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const PolarSample& s = samples[static_cast<std::size_t>(i)];
    const double x = (s.radius_px - polynomial.offset_px) / polynomial.scale_px;
    double power = 1.0;
    for (Eigen::Index k = 0; k < vandermonde.cols(); ++k, power *= x) vandermonde(i, k) = power;
    distances(i) = s.distance_cm;
  }
  const Eigen::VectorXd a = vandermonde.colPivHouseholderQr().solve(distances);  // Eq. 1
  polynomial.coefficients.assign(a.data(), a.data() + a.size());
  return {std::move(polynomial), {image, valid_radius_from_samples(samples)}};
}

}  // namespace ballsight
