#include "ballsight/camera/distortion.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

Distortion::Distortion(const Coefficients& coefficients) : c_(coefficients) {
  for (double c : c_) require(std::isfinite(c), "distortion", "coefficients must be finite");
  // Walk outwards until r * radial(r) stops increasing: beyond that radius the model folds back
  // and a distorted point has several preimages.
  constexpr double kStep = 1e-3;
  double previous = 0.0;
  for (double r = kStep; r <= kMaxRadiusCap; r += kStep) {
    const double rd = r * radial_factor(r * r);
    if (!(rd > previous)) {
      max_radius_ = r - kStep;
      break;
    }
    previous = rd;
  }
  require(max_radius_ > 0.1, "distortion", "model folds back within 0.1 of the optical axis");
}

bool Distortion::is_zero() const {
  for (double c : c_)
    if (c != 0.0) return false;
  return true;
}

double Distortion::radial_factor(double r2, double* slope) const {
  const auto& [k1, k2, p1, p2, k3, k4, k5, k6] = c_;
  (void)p1;
  (void)p2;
  const double numerator = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double denominator = 1.0 + r2 * (k4 + r2 * (k5 + r2 * k6));
  if (slope) {
    *slope = ((k1 + r2 * (2.0 * k2 + 3.0 * r2 * k3)) * denominator -
              numerator * (k4 + r2 * (2.0 * k5 + 3.0 * r2 * k6))) /
             (denominator * denominator);
  }
  return numerator / denominator;
}

Vec2 Distortion::distort(const Vec2& m) const {
  return distort(m, nullptr);
}

Vec2 Distortion::distort(const Vec2& m, Eigen::Matrix2d* jacobian) const {
  const double x = m.x(), y = m.y();
  const double r2 = x * x + y * y;
  const double p1 = c_[2], p2 = c_[3];
  double slope = 0.0;  // d radial / d r2
  const double radial = radial_factor(r2, jacobian ? &slope : nullptr);
  if (jacobian) {
    // The chain through r2 = x^2 + y^2, and the tangential terms.
    const double cross = 2.0 * x * y * slope + 2.0 * p1 * x + 2.0 * p2 * y;
    *jacobian << radial + 2.0 * x * x * slope + 2.0 * p1 * y + 6.0 * p2 * x, cross, cross,
        radial + 2.0 * y * y * slope + 6.0 * p1 * y + 2.0 * p2 * x;
  }
  return {x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
          y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y};
}

std::optional<Vec2> Distortion::undistort(const Vec2& md) const {
  if (is_zero()) return md;
  Vec2 m = md;
  // Newton with the model's own Jacobian; converges in a handful of steps inside the valid region.
  Eigen::Matrix2d jacobian;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Vec2 residual = distort(m, &jacobian) - md;
    if (residual.squaredNorm() < 1e-26) break;
    m -= jacobian.inverse() * residual;
    if (!m.allFinite()) return std::nullopt;
  }
  if (m.norm() > max_radius_ || (distort(m) - md).norm() > 1e-10) return std::nullopt;
  return m;
}

}  // namespace ballsight
