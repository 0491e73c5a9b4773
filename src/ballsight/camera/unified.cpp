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
      model_{params.xi},
      distortion_((params.validate(), Distortion::Coefficients{params.k1, params.k2, params.p1,
                                                               params.p2, 0, 0, 0, 0})) {}

std::optional<Vec3> UnifiedCamera::unproject(const Vec2& pixel) const {
  const Vec2 md((pixel.x() - params_.cx) / params_.fx, (pixel.y() - params_.cy) / params_.fy);
  const std::optional<Vec2> m = distortion_.undistort(md);
  Vec3 ray;
  if (!m || !model_.lift(m->x(), m->y(), ray.data())) return std::nullopt;
  return ray;
}

std::optional<Vec2> UnifiedCamera::project(const Vec3& p_in_camera) const {
  Vec2 m;
  if (!model_.project(p_in_camera.data(), m.data())) return std::nullopt;
  if (m.norm() > distortion_.max_radius()) return std::nullopt;
  const Vec2 md = distortion_.distort(m);
  return Vec2(params_.fx * md.x() + params_.cx, params_.fy * md.y() + params_.cy);
}

}  // namespace ballsight
