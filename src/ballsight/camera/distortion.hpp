#pragma once
// OpenCV's lens distortion model (Brown-Conrady with the rational extension) on normalised image
// coordinates: coefficients k1, k2, p1, p2, k3, k4, k5, k6 in OpenCV's order.

#include <array>
#include <optional>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

class Distortion {
 public:
  using Coefficients = std::array<double, 8>;  // k1 k2 p1 p2 k3 k4 k5 k6

  Distortion() = default;
  /// Throws InputError when the coefficients make the model non-invertible near the centre.
  explicit Distortion(const Coefficients& coefficients);

  const Coefficients& coefficients() const { return c_; }
  bool is_zero() const;

  /// Undistorted -> distorted normalised coordinates.
  Vec2 distort(const Vec2& m) const;
  /// Distorted -> undistorted by Newton's method; nullopt outside the invertible region.
  std::optional<Vec2> undistort(const Vec2& md) const;

  /// Largest undistorted radius up to which the radial part stays strictly increasing (capped).
  double max_radius() const { return max_radius_; }

 private:
  // The rational radial factor at r2 = |m|^2 and, if `slope` is given, its derivative by r2.
  double radial_factor(double r2, double* slope = nullptr) const;
  // distort() and, if `jacobian` is given, its derivative by m there.
  Vec2 distort(const Vec2& m, Eigen::Matrix2d* jacobian) const;

  Coefficients c_{};
  double max_radius_ = kMaxRadiusCap;
  static constexpr double kMaxRadiusCap = 10.0;
};

}  // namespace ballsight
