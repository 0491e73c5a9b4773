#pragma once
// Ray casting primitives shared by the simulators' renderers. Rays are `origin + t * direction`
// with a unit direction; hits report the smallest positive t.

#include <cmath>
#include <opencv2/core.hpp>
#include <optional>

#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

/// First hit of a ray with a sphere, or nullopt.
inline std::optional<double> intersect_sphere(const Vec3& origin, const Vec3& direction,
                                              const Vec3& center, double radius) {
  const Vec3 oc = origin - center;
  const double b = oc.dot(direction);
  const double c = oc.squaredNorm() - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  const double t = -b - root;
  if (t > 1e-9) return t;
  const double t_far = -b + root;
  return t_far > 1e-9 ? std::optional<double>(t_far) : std::nullopt;
}

/// Hit of a ray with the horizontal plane z = height, or nullopt.
inline std::optional<double> intersect_horizontal_plane(const Vec3& origin, const Vec3& direction,
                                                        double height) {
  if (std::abs(direction.z()) < 1e-12) return std::nullopt;
  const double t = (height - origin.z()) / direction.z();
  return t > 1e-9 ? std::optional<double>(t) : std::nullopt;
}

/// Diffuse shading of a base colour for a surface normal under a light from `to_light` plus an
/// ambient term; both unit vectors.
inline cv::Vec3b shade(const cv::Vec3b& base, const Vec3& normal, const Vec3& to_light,
                       double ambient = 0.45) {
  const double lambert = std::max(0.0, normal.dot(to_light));
  const double k = ambient + (1.0 - ambient) * lambert;
  return {cv::saturate_cast<uchar>(base[0] * k), cv::saturate_cast<uchar>(base[1] * k),
          cv::saturate_cast<uchar>(base[2] * k)};
}

}  // namespace ballsight::sim
