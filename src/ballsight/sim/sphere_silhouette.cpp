#include "ballsight/sim/sphere_silhouette.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"

namespace ballsight::sim {

std::optional<std::vector<Vec2>> sphere_silhouette(const PinholeCamera& camera,
                                                   const Vec3& center_in_camera, double radius,
                                                   int count) {
  const double d = center_in_camera.norm();
  if (!(d > radius)) return std::nullopt;
  // Tangent points lie on a circle of radius r sqrt(d^2 - r^2) / d around the point r^2 / d in
  // front of the centre, seen from the camera.
  const Vec3 axis = center_in_camera / d;
  const Vec3 rim_center = center_in_camera - axis * (radius * radius / d);
  const double rim_radius = radius * std::sqrt(d * d - radius * radius) / d;
  const Vec3 e1 = axis.unitOrthogonal();
  const Vec3 e2 = axis.cross(e1);
  std::vector<Vec2> pixels;
  pixels.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * kPi * i / count;
    const Vec3 p = rim_center + rim_radius * (std::cos(a) * e1 + std::sin(a) * e2);
    const std::optional<Vec2> pixel = camera.project(p);
    if (!pixel) return std::nullopt;
    pixels.push_back(*pixel);
  }
  return pixels;
}

Vec2 polygon_centroid(const std::vector<Vec2>& polygon) {
  double area2 = 0.0;
  Vec2 weighted = Vec2::Zero();
  Vec2 mean = Vec2::Zero();
  const Vec2 origin = polygon.empty() ? Vec2::Zero() : polygon.front();  // for conditioning
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i] - origin;
    const Vec2 b = polygon[(i + 1) % polygon.size()] - origin;
    const double cross = a.x() * b.y() - b.x() * a.y();
    area2 += cross;
    weighted += (a + b) * cross;
    mean += polygon[i];
  }
  if (std::abs(area2) < 1e-12)
    return polygon.empty() ? mean : Vec2(mean / static_cast<double>(polygon.size()));
  return origin + weighted / (3.0 * area2);
}

}  // namespace ballsight::sim
