#include "ballsight/camera/unified.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void UnifiedParams::validate() const {
  require(width > 0 && height > 0, "unified camera", "image size must be positive");
  require(std::isfinite(xi) && xi >= 0.0, "unified camera", "xi must be >= 0");
  require(std::isfinite(fx) && fx > 0.0 && std::isfinite(fy) && fy > 0.0, "unified camera",
          "focal lengths fx, fy must be positive");
  require(std::isfinite(cx) && std::isfinite(cy), "unified camera",
          "principal point must be finite");
}

UnifiedCamera::UnifiedCamera(const UnifiedParams& params)
    : params_(params),
      distortion_((params.validate(), Distortion::Coefficients{params.k1, params.k2, params.p1,
                                                               params.p2, 0, 0, 0, 0})) {}

std::optional<Vec3> UnifiedCamera::unproject(const Vec2& pixel) const {
  const Vec2 md((pixel.x() - params_.cx) / params_.fx, (pixel.y() - params_.cy) / params_.fy);
  const std::optional<Vec2> m = distortion_.undistort(md);
  if (!m) return std::nullopt;
  // Lift the normalised point back onto the unit sphere (closed form of the unified model).
  const double xi = params_.xi;
  const double r2 = m->squaredNorm();
  const double discriminant = 1.0 + (1.0 - xi * xi) * r2;
  if (discriminant < 0.0) return std::nullopt;
  const double factor = (xi + std::sqrt(discriminant)) / (1.0 + r2);
  const Vec3 ray(factor * m->x(), factor * m->y(), factor - xi);
  if (xi > 1.0 && ray.z() < -1.0 / xi) return std::nullopt;  // the fold of the model
  return ray;
}

std::optional<Vec2> UnifiedCamera::project(const Vec3& p_in_camera) const {
  const double norm = p_in_camera.norm();
  if (!(norm > 0.0)) return std::nullopt;
  const Vec3 s = p_in_camera / norm;
  const double xi = params_.xi;
  const double denominator = s.z() + xi;
  if (denominator <= 1e-12) return std::nullopt;
  if (xi > 1.0 && s.z() < -1.0 / xi) return std::nullopt;
  const Vec2 m = s.head<2>() / denominator;
  if (1.0 + (1.0 - xi * xi) * m.squaredNorm() < 0.0) return std::nullopt;
  if (m.norm() > distortion_.max_radius()) return std::nullopt;
  const Vec2 md = distortion_.distort(m);
  return Vec2(params_.fx * md.x() + params_.cx, params_.fy * md.y() + params_.cy);
}

}  // namespace ballsight
