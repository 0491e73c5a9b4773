#include "ballsight/calib/radial_warp.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

namespace {

// The four non-zero uniform cubic B-spline weights at fraction u of a segment.
std::array<double, 4> cubic_weights(double u) {
  const double v = 1.0 - u;
  return {v * v * v / 6.0, (3.0 * u * u * u - 6.0 * u * u + 4.0) / 6.0,
          (-3.0 * u * u * u + 3.0 * u * u + 3.0 * u + 1.0) / 6.0, u * u * u / 6.0};
}

// The segment and fraction of `t` in [0, segments]: the last segment includes its end.
std::pair<int, double> segment_of(double t, int segments) {
  const int i = std::clamp(static_cast<int>(std::floor(t)), 0, segments - 1);
  return {i, t - i};
}

struct Basis {
  std::array<int, 16> index;
  std::array<double, 16> weight;
};

Basis basis_at(double theta_deg, double radius_px, int theta_segments, const RadiusRange& span,
               int radius_segments) {
  const double turn = std::fmod(std::fmod(theta_deg, 360.0) + 360.0, 360.0);
  const auto [ti, tu] = segment_of(turn / 360.0 * theta_segments, theta_segments);
  const double width = std::max(span.max_px - span.min_px, 1e-9);
  const double r = std::clamp(radius_px, span.min_px, span.max_px);
  const auto [ri, ru] = segment_of((r - span.min_px) / width * radius_segments, radius_segments);
  const std::array<double, 4> wt = cubic_weights(tu), wr = cubic_weights(ru);
  const int radius_basis = radius_segments + 3;
  Basis basis;
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      basis.index[4 * a + b] = ((ti + a) % theta_segments) * radius_basis + ri + b;
      basis.weight[4 * a + b] = wt[a] * wr[b];
    }
  }
  return basis;
}

// Second differences along one axis of the theta-major coefficient grid, circular in theta.
Eigen::MatrixXd difference_penalty(int theta_basis, int radius_basis, bool along_theta) {
  const int n = theta_basis * radius_basis;
  Eigen::MatrixXd penalty = Eigen::MatrixXd::Zero(n, n);
  const auto add_row = [&](int a, int b, int c) {
    const int idx[3] = {a, b, c};
    const double coef[3] = {1.0, -2.0, 1.0};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) penalty(idx[i], idx[j]) += coef[i] * coef[j];
    }
  };
  for (int t = 0; t < theta_basis; ++t) {
    for (int r = 0; r < radius_basis; ++r) {
      if (along_theta) {
        if (theta_basis < 3) continue;
        add_row(((t + theta_basis - 1) % theta_basis) * radius_basis + r, t * radius_basis + r,
                ((t + 1) % theta_basis) * radius_basis + r);
      } else if (r >= 1 && r + 1 < radius_basis) {
        add_row(t * radius_basis + r - 1, t * radius_basis + r, t * radius_basis + r + 1);
      }
    }
  }
  return penalty;
}

}  // namespace

RadialWarp::RadialWarp(int theta_segments, RadiusRange span, int radius_segments,
                       std::vector<double> coefficients)
    : theta_segments_(theta_segments),
      span_(span),
      radius_segments_(radius_segments),
      coefficients_(std::move(coefficients)) {}

double RadialWarp::operator()(double theta_deg, double radius_px) const {
  const Basis basis = basis_at(theta_deg, radius_px, theta_segments_, span_, radius_segments_);
  double shift = 0.0;
  for (int k = 0; k < 16; ++k) shift += basis.weight[k] * coefficients_[basis.index[k]];
  return shift;
}

nlohmann::json RadialWarp::to_json() const {
  return {{"theta_segments", theta_segments_},
          {"radius_span_px", {span_.min_px, span_.max_px}},
          {"radius_segments", radius_segments_},
          {"coefficients", coefficients_}};
}

RadialWarp RadialWarp::from_json(const nlohmann::json& value, const std::string& where) {
  const int theta_segments = json_int(value, "theta_segments", where, 3, 360);
  const int radius_segments = json_int(value, "radius_segments", where, 1, 100);
  const std::vector<double> span = json_numbers(value, "radius_span_px", where, 2);
  require(span[0] >= 0.0 && span[1] > span[0], where + ".radius_span_px",
          "expected [min, max] with 0 <= min < max");
  const auto count = static_cast<std::size_t>(theta_segments * (radius_segments + 3));
  std::vector<double> coefficients = json_numbers(value, "coefficients", where, count);
  return {theta_segments, {span[0], span[1]}, radius_segments, std::move(coefficients)};
}

RadialWarp fit_radial_warp(std::span<const WarpTarget> targets,
                           const RadialWarpFitOptions& options) {
  require(!targets.empty(), "warp targets", "expected at least one");
  require(std::all_of(targets.begin(), targets.end(),
                      [](const WarpTarget& t) {
                        return std::isfinite(t.theta_deg) && std::isfinite(t.radius_px) &&
                               std::isfinite(t.shift_px);
                      }),
          "warp targets", "expected finite angles, radii and shifts");
  require(options.theta_segments >= 3 && options.radius_segments >= 1, "warp segments",
          "expected at least 3 around and 1 along the radius");
  require(options.theta_smoothing > 0.0 && options.radius_smoothing > 0.0, "warp smoothing",
          "expected positive penalties");
  RadiusRange span{INFINITY, -INFINITY};
  for (const WarpTarget& t : targets) {
    span.min_px = std::min(span.min_px, t.radius_px);
    span.max_px = std::max(span.max_px, t.radius_px);
  }
  span.max_px = std::max(span.max_px, span.min_px + 1.0);
  const int theta_basis = options.theta_segments;
  const int radius_basis = options.radius_segments + 3;
  const int n = theta_basis * radius_basis;
  // Penalties relative to the data's weight per coefficient; a small ridge pulls coefficients
  // no sample reaches to zero (the physical model).
  const double scale = static_cast<double>(targets.size()) / n;
  Eigen::MatrixXd penalty = difference_penalty(theta_basis, radius_basis, true);
  penalty *= scale * options.theta_smoothing;
  penalty +=
      scale * options.radius_smoothing * difference_penalty(theta_basis, radius_basis, false);
  penalty.diagonal().array() += 1e-4 * scale;
  std::vector<Basis> bases;
  bases.reserve(targets.size());
  for (const WarpTarget& t : targets) {
    bases.push_back(basis_at(t.theta_deg, t.radius_px, theta_basis, span, options.radius_segments));
  }
  std::vector<double> weights(targets.size(), 1.0);
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd normal(n, n);
  Eigen::VectorXd rhs(n);
  // Sparse: a coefficient meets only its neighbours within three segments (a sample's 4 x 4
  // basis, the penalties' second differences).
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> solver;  // penalty + ridge: positive definite
  for (int pass = 0; pass < std::max(1, options.reweighting_passes); ++pass) {
    normal = penalty;
    rhs.setZero();
    for (std::size_t i = 0; i < targets.size(); ++i) {
      const Basis& b = bases[i];
      for (int j = 0; j < 16; ++j) {
        rhs(b.index[j]) += weights[i] * b.weight[j] * targets[i].shift_px;
        for (int k = 0; k < 16; ++k) {
          normal(b.index[j], b.index[k]) += weights[i] * b.weight[j] * b.weight[k];
        }
      }
    }
    solver.compute(normal.sparseView());
    require(solver.info() == Eigen::Success, "warp fit",
            "the normal equations are not positive definite");
    coefficients = solver.solve(rhs);
    std::vector<double> residuals(targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i) {
      double fitted = 0.0;
      for (int j = 0; j < 16; ++j) fitted += bases[i].weight[j] * coefficients(bases[i].index[j]);
      residuals[i] = std::abs(fitted - targets[i].shift_px);
    }
    const double k = std::max(options.huber_px, 2.0 * 1.4826 * median(residuals));
    for (std::size_t i = 0; i < targets.size(); ++i) {
      weights[i] = residuals[i] <= k ? 1.0 : k / residuals[i];
    }
  }
  return {theta_basis, span, options.radius_segments,
          std::vector<double>(coefficients.data(), coefficients.data() + n)};
}

}  // namespace ballsight
