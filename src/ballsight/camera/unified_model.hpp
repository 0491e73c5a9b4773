#pragma once
// The unified central catadioptric model (Mei & Rives 2007) without the lens: a point is projected
// onto the unit sphere, then through a pinhole shifted by `xi` along the axis onto the normalised
// image plane. Written once, as a small value type templated on the scalar (a double, or a Ceres
// Jet for autodiff): camera/unified.hpp puts a lens and a camera matrix after it (the simulator's
// and cv::omnidir's camera), calib/catadioptric_floor.hpp a mount above the floor (the omni
// calibration's fit).

#include <cmath>

namespace ballsight {

template <typename T>
struct UnifiedModel {
  T xi;

  /// Normalised image point (mx, my) -> its ray on the unit sphere, in closed form (the root
  /// nearer the pinhole, so never beyond the fold of project()); false where the point lies
  /// beyond the model's image (1 + (1 - xi^2) |m|^2 <= 0, only for xi > 1).
  bool lift(const T& mx, const T& my, T ray[3]) const {
    const T r2 = mx * mx + my * my;
    const T discriminant = T(1.0) + (T(1.0) - xi * xi) * r2;
    if (!(discriminant > T(0.0))) return false;
    using std::sqrt;
    const T factor = (xi + sqrt(discriminant)) / (T(1.0) + r2);
    ray[0] = factor * mx;
    ray[1] = factor * my;
    ray[2] = factor - xi;
    return true;
  }

  /// A point (at any distance) -> its normalised image point; false where it has no unique one:
  /// behind the shifted pinhole (z + xi |p| <= 0) or, for xi > 1, on or beyond the fold where
  /// two points of the sphere share a pixel (z / |p| <= -1 / xi, the border of lift()'s image).
  bool project(const T p[3], T m[2]) const {
    using std::sqrt;
    const T norm = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const T denominator = p[2] + xi * norm;
    if (!(denominator > T(0.0))) return false;
    if (xi > T(1.0) && p[2] * xi <= -norm) return false;
    m[0] = p[0] / denominator;
    m[1] = p[1] / denominator;
    return true;
  }
};

}  // namespace ballsight
