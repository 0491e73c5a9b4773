#include "ballsight/sim/silhouette.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"

namespace ballsight::sim {

namespace {

std::vector<Vec3> circle_points(const Vec3& center, const Vec3& normal, double radius,
                                int samples) {
  const Vec3 e1 = normal.unitOrthogonal();
  const Vec3 e2 = normal.cross(e1);
  std::vector<Vec3> points;
  points.reserve(samples);
  for (int i = 0; i < samples; ++i) {
    const double phi = 2.0 * kPi * i / samples;
    points.push_back(center + radius * (std::cos(phi) * e1 + std::sin(phi) * e2));
  }
  return points;
}

}  // namespace

std::vector<Vec3> sphere_silhouette(const Vec3& viewpoint, const Vec3& center, double radius,
                                    int samples) {
  const Vec3 to_center = center - viewpoint;
  const double d = to_center.norm();
  if (!(d > radius)) return {};
  const Vec3 u = to_center / d;
  // The tangent cone touches the sphere on a circle centred d - r^2/d along the axis, with
  // radius r * sqrt(d^2 - r^2) / d.
  const double along = d - radius * radius / d;
  const double rim_radius = radius * std::sqrt(d * d - radius * radius) / d;
  return circle_points(viewpoint + along * u, u, rim_radius, samples);
}

std::vector<Vec3> floor_disc_rim(const Vec2& center, double radius, int samples) {
  return circle_points({center.x(), center.y(), 0.0}, Vec3::UnitZ(), radius, samples);
}

std::optional<std::vector<Vec2>> project_outline(const OmniRig& rig,
                                                 const std::vector<Vec3>& points_in_robot) {
  std::vector<Vec2> pixels;
  pixels.reserve(points_in_robot.size());
  for (const Vec3& p : points_in_robot) {
    const std::optional<Vec2> pixel = rig.project(p);
    if (!pixel) return std::nullopt;
    pixels.push_back(*pixel);
  }
  return pixels;
}

std::optional<std::vector<Vec2>> sphere_outline_pixels(const PinholeCamera& camera,
                                                       const Vec3& center_in_camera, double radius,
                                                       int samples) {
  const std::vector<Vec3> rim = sphere_silhouette(Vec3::Zero(), center_in_camera, radius, samples);
  if (rim.empty()) return std::nullopt;
  std::vector<Vec2> pixels;
  pixels.reserve(rim.size());
  for (const Vec3& p : rim) {
    const std::optional<Vec2> pixel = camera.project(p);
    if (!pixel) return std::nullopt;
    pixels.push_back(*pixel);
  }
  return pixels;
}

bool inside_mirror(const OmniRig& rig, const std::vector<Vec2>& pixels) {
  for (const Vec2& p : pixels) {
    if ((p - rig.principal_point()).norm() > rig.params().mirror_radius_px) return false;
  }
  return true;
}

std::optional<Vec2> polygon_centroid(const std::vector<Vec2>& polygon) {
  double twice_area = 0.0;
  Vec2 weighted = Vec2::Zero();
  const std::size_t n = polygon.size();
  // Shoelace about the first vertex, which keeps the sums small for small far-away polygons.
  const Vec2 origin = n > 0 ? polygon[0] : Vec2::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = polygon[i] - origin;
    const Vec2 b = polygon[(i + 1) % n] - origin;
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice_area += cross;
    weighted += cross * (a + b);
  }
  if (std::abs(twice_area) < 1e-12) return std::nullopt;
  return origin + weighted / (3.0 * twice_area);
}

}  // namespace ballsight::sim
