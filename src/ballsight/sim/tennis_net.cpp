#include "ballsight/sim/tennis_net.hpp"

#include <cmath>

namespace ballsight::sim {
namespace {

constexpr double kMinT = 1e-9;

/// Keeps the nearer of two hits.
void keep_nearest(std::optional<NetHit>& best, const NetHit& hit) {
  if (hit.t > kMinT && (!best || hit.t < best->t)) best = hit;
}

}  // namespace

std::optional<TennisNet> TennisNet::of(const TennisCourtSpec& court) {
  if (!court.net.enabled) return std::nullopt;
  return TennisNet(court.net, court.doubles_width_m / 2.0 + court.net.post_outside_doubles_m);
}

std::array<Vec2, 2> TennisNet::post_positions() const {
  return {Vec2(0.0, -post_y_m_), Vec2(0.0, post_y_m_)};
}

double TennisNet::top_height_m(double y_m) const {
  return spec_.centre_height_m +
         (spec_.post_height_m - spec_.centre_height_m) * std::abs(y_m) / post_y_m_;
}

FloorBox TennisNet::bounds() const {
  const double r = spec_.post_radius_m;
  return {Pose2D{Vec2::Zero(), 0.0}, Vec2(r, post_y_m_ + r), spec_.post_height_m};
}

std::optional<NetHit> TennisNet::intersect(const Vec3& origin, const Vec3& direction) const {
  std::optional<NetHit> best;
  // The net plane x = 0, facing the side the ray comes from.
  if (std::abs(direction.x()) > 1e-12) {
    const double t = -origin.x() / direction.x();
    const double y = origin.y() + t * direction.y(), z = origin.z() + t * direction.z();
    const double top = std::abs(y) <= post_y_m_ ? top_height_m(y) : -1.0;
    if (z >= 0.0 && z <= top) {
      const NetPart part = z >= top - spec_.band_depth_m ? NetPart::band : NetPart::mesh;
      keep_nearest(best, {t, Vec3(direction.x() > 0.0 ? -1.0 : 1.0, 0.0, 0.0), part});
    }
  }
  // The posts: vertical cylinders from the floor to post_height_m, with a flat top.
  const double r = spec_.post_radius_m, h = spec_.post_height_m;
  const Vec2 d_xy = direction.head<2>();
  const double a = d_xy.squaredNorm();
  for (const Vec2& post : post_positions()) {
    const Vec2 rel = origin.head<2>() - post;
    if (a > 1e-24) {
      const double b = rel.dot(d_xy), c = rel.squaredNorm() - r * r;
      const double discriminant = b * b - a * c;
      if (discriminant >= 0.0) {
        const double t = (-b - std::sqrt(discriminant)) / a;
        const double z = origin.z() + t * direction.z();
        if (z >= 0.0 && z <= h) {
          const Vec2 n = (rel + t * d_xy) / r;
          keep_nearest(best, {t, Vec3(n.x(), n.y(), 0.0), NetPart::post});
        }
      }
    }
    if (std::abs(direction.z()) > 1e-12) {
      const double t = (h - origin.z()) / direction.z();
      if ((rel + t * d_xy).squaredNorm() <= r * r) {
        keep_nearest(best, {t, Vec3(0.0, 0.0, direction.z() < 0.0 ? 1.0 : -1.0), NetPart::post});
      }
    }
  }
  return best;
}

const cv::Vec3b& TennisNet::albedo(NetPart part) const {
  switch (part) {
    case NetPart::band:
      return spec_.band_bgr;
    case NetPart::post:
      return spec_.post_bgr;
    case NetPart::mesh:
      break;
  }
  return spec_.mesh_bgr;
}

}  // namespace ballsight::sim
