#include "ballsight/camera/mirror_tracer.hpp"

#include <cmath>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/enum_names.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

constexpr EnumNames<MirrorKind, 4> kMirrorKindNames{{{MirrorKind::kUnified, "unified"},
                                                     {MirrorKind::kSphere, "sphere"},
                                                     {MirrorKind::kCone, "cone"},
                                                     {MirrorKind::kTable, "table"}}};
constexpr int kBisections = 60;
constexpr int kProjectionScan = 400;  // radius steps searched for the reflection

// Fritsch-Carlson slopes of a monotone cubic through the table's points.
std::vector<double> monotone_slopes(const std::vector<Vec2>& t) {
  const std::size_t n = t.size();
  std::vector<double> delta(n - 1), m(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    delta[i] = (t[i + 1].y() - t[i].y()) / (t[i + 1].x() - t[i].x());
  }
  m[0] = delta[0];
  m[n - 1] = delta[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    m[i] = delta[i - 1] * delta[i] <= 0.0 ? 0.0 : 0.5 * (delta[i - 1] + delta[i]);
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (delta[i] == 0.0) {
      m[i] = m[i + 1] = 0.0;
      continue;
    }
    const double a = m[i] / delta[i], b = m[i + 1] / delta[i];
    const double s = a * a + b * b;
    if (s > 9.0) {
      m[i] = 3.0 * a / std::sqrt(s) * delta[i];
      m[i + 1] = 3.0 * b / std::sqrt(s) * delta[i];
    }
  }
  return m;
}

// The table's height (derivative = false) or slope at rho, `m` its monotone_slopes; linear
// beyond its last point.
double table_value(const std::vector<Vec2>& t, const std::vector<double>& m, double rho,
                   bool derivative) {
  if (rho >= t.back().x()) {
    return derivative ? m.back() : t.back().y() + m.back() * (rho - t.back().x());
  }
  std::size_t i = 0;
  while (i + 2 < t.size() && rho > t[i + 1].x()) ++i;
  const double h = t[i + 1].x() - t[i].x();
  const double s = (rho - t[i].x()) / h;
  if (derivative) {
    return ((6 * s * s - 6 * s) * t[i].y() + (3 * s * s - 4 * s + 1) * h * m[i] +
            (-6 * s * s + 6 * s) * t[i + 1].y() + (3 * s * s - 2 * s) * h * m[i + 1]) /
           h;
  }
  return (2 * s * s * s - 3 * s * s + 1) * t[i].y() + (s * s * s - 2 * s * s + s) * h * m[i] +
         (-2 * s * s * s + 3 * s * s) * t[i + 1].y() + (s * s * s - s * s) * h * m[i + 1];
}

// The mirror's reflection of the camera ray `d` (unit) at a surface point of radius rho and
// outward unit direction `outward` in the horizontal plane.
Vec3 reflect(const Vec3& d, double slope, const Vec2& outward) {
  const Vec3 n = Vec3(-slope * outward.x(), -slope * outward.y(), 1.0).normalized();
  return d - 2.0 * d.dot(n) * n;
}

}  // namespace

std::string_view mirror_kind_name(MirrorKind kind) {
  return enum_name(kMirrorKindNames, kind);
}

std::optional<MirrorKind> mirror_kind_named(std::string_view name) {
  return enum_named(kMirrorKindNames, name);
}

MirrorKind parse_mirror_kind(std::string_view name, const std::string& where) {
  if (const std::optional<MirrorKind> kind = mirror_kind_named(name)) return *kind;
  throw InputError(where + ": unknown mirror '" + std::string(name) +
                   "'; expected unified, sphere, cone or table");
}

MirrorProfile default_mirror(MirrorKind kind) {
  MirrorProfile profile;
  profile.kind = kind;
  profile.cone_half_angle_deg = 60.0;
  if (kind == MirrorKind::kTable) {
    // Height rho^2 / (2 R1) with R1 = 5 cm up to the knee at 2.4 cm, then a surface curving
    // as R2 = 2.2 cm with the same slope at the knee: one table point every 2 mm.
    constexpr double kR1 = 0.05, kR2 = 0.022, kKnee = 0.024;
    const double knee_height = kKnee * kKnee / (2.0 * kR1);
    const double knee_slope = kKnee / kR1;
    for (int i = 0; i <= 22; ++i) {
      const double rho = 0.002 * i;
      const double beyond = std::max(0.0, rho - kKnee);
      const double h = rho <= kKnee
                           ? rho * rho / (2.0 * kR1)
                           : knee_height + knee_slope * beyond + beyond * beyond / (2.0 * kR2);
      profile.table_m.push_back({rho, h});
    }
  }
  return profile;
}

void MirrorProfile::validate() const {
  if (kind == MirrorKind::kUnified) return;
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(rim_radius_m) && rim_radius_m <= 0.5, "mirror.rim_radius_m",
          "expected a positive radius up to 0.5 m");
  require(positive(apex_above_camera_m) && apex_above_camera_m <= 2.0, "mirror.apex_above_camera_m",
          "expected a positive distance up to 2 m");
  if (kind == MirrorKind::kSphere) {
    require(positive(sphere_radius_m) && sphere_radius_m > rim_radius_m, "mirror.sphere_radius_m",
            "expected a radius larger than the rim's");
  }
  if (kind == MirrorKind::kCone) {
    require(std::isfinite(cone_half_angle_deg) && cone_half_angle_deg > 20.0 &&
                cone_half_angle_deg < 85.0,
            "mirror.cone_half_angle_deg", "expected 20 to 85 deg");
  }
  if (kind == MirrorKind::kTable) {
    require(table_m.size() >= 3 && table_m.front().x() == 0.0 && table_m.front().y() == 0.0,
            "mirror.table_m", "expected at least 3 points from (0, 0)");
    for (std::size_t i = 1; i < table_m.size(); ++i) {
      require(table_m[i].allFinite() && table_m[i].x() > table_m[i - 1].x() &&
                  table_m[i].y() >= table_m[i - 1].y(),
              "mirror.table_m", "expected radius increasing and height not decreasing");
    }
    require(table_m.back().x() >= rim_radius_m, "mirror.table_m", "expected to reach the rim");
  }
  require(std::isfinite(ripple_amplitude_m) && std::abs(ripple_amplitude_m) <= 0.001,
          "mirror.ripple_amplitude_m", "expected at most 1 mm");
  require(positive(ripple_period_m), "mirror.ripple_period_m", "expected a positive period");
  require(std::isfinite(lens_k1) && std::abs(lens_k1) <= 1.0, "mirror.lens_k1", "expected -1 to 1");
}

MirrorTracer::MirrorTracer(const MirrorProfile& profile, double focal_px, const Vec2& principal_px)
    : profile_(profile), focal_px_(focal_px), principal_px_(principal_px) {
  profile_.validate();
  require(profile_.kind != MirrorKind::kUnified, "mirror", "the unified model is not traced");
  if (profile_.kind == MirrorKind::kTable) table_slopes_ = monotone_slopes(profile_.table_m);
}

double MirrorTracer::height(double rho) const {
  double h = 0.0;
  switch (profile_.kind) {
    case MirrorKind::kSphere: {
      const double r = profile_.sphere_radius_m;
      h = r - std::sqrt(r * r - rho * rho);
      break;
    }
    case MirrorKind::kCone:
      h = rho / std::tan(rad_from_deg(profile_.cone_half_angle_deg));
      break;
    case MirrorKind::kTable:
      h = table_value(profile_.table_m, table_slopes_, rho, false);
      break;
    case MirrorKind::kUnified:
      break;
  }
  return h + profile_.ripple_amplitude_m * std::sin(2.0 * kPi * rho / profile_.ripple_period_m);
}

double MirrorTracer::slope(double rho) const {
  double s = 0.0;
  switch (profile_.kind) {
    case MirrorKind::kSphere: {
      const double r = profile_.sphere_radius_m;
      s = rho / std::sqrt(r * r - rho * rho);
      break;
    }
    case MirrorKind::kCone:
      s = 1.0 / std::tan(rad_from_deg(profile_.cone_half_angle_deg));
      break;
    case MirrorKind::kTable:
      s = table_value(profile_.table_m, table_slopes_, rho, true);
      break;
    case MirrorKind::kUnified:
      break;
  }
  const double k = 2.0 * kPi / profile_.ripple_period_m;
  return s + profile_.ripple_amplitude_m * k * std::cos(k * rho);
}

double MirrorTracer::focal_for_rim(const MirrorProfile& profile, double rim_px) {
  const MirrorTracer unit(profile, 1.0, Vec2::Zero());
  const double r =
      profile.rim_radius_m / (profile.apex_above_camera_m + unit.height(profile.rim_radius_m));
  return rim_px / (r * (1.0 + profile.lens_k1 * r * r));
}

std::optional<TracedRay> MirrorTracer::trace(const Vec2& pixel) const {
  const Vec2 distorted = (pixel - principal_px_) / focal_px_;
  Vec2 x = distorted;
  for (int i = 0; i < 20; ++i) x = distorted / (1.0 + profile_.lens_k1 * x.squaredNorm());
  // The flipped image: up is +x (forward), right is -y (the robot's right).
  const Vec3 d = Vec3(-x.y(), -x.x(), 1.0).normalized();
  const double rho_d = std::hypot(d.x(), d.y());
  const double a = profile_.apex_above_camera_m;
  const auto below = [&](double t) { return t * d.z() - a - height(t * rho_d); };
  double t_hi = rho_d > 0.0 ? profile_.rim_radius_m / rho_d : 2.0 * a / d.z();
  if (below(t_hi) < 0.0) return std::nullopt;  // passes the rim
  double t_lo = 0.0;
  for (int i = 0; i < kBisections; ++i) {
    const double t = 0.5 * (t_lo + t_hi);
    (below(t) < 0.0 ? t_lo : t_hi) = t;
  }
  const Vec3 hit = 0.5 * (t_lo + t_hi) * d;
  const double rho = std::hypot(hit.x(), hit.y());
  const Vec2 outward = rho > 0.0 ? Vec2(Vec2(hit.x(), hit.y()) / rho) : Vec2(Vec2::UnitX());
  return TracedRay{hit, reflect(d, slope(rho), outward)};
}

std::optional<Vec2> MirrorTracer::project(const Vec3& point) const {
  const double distance = std::hypot(point.x(), point.y());
  if (!(distance > 1e-9)) return std::nullopt;
  const Vec2 outward = Vec2(point.x(), point.y()) / distance;
  const double a = profile_.apex_above_camera_m;
  // In the point's azimuth plane: the reflection at radius rho misses the point on one side or
  // the other (the sign of the cross product); the root is the mirror point that sees it.
  const auto miss = [&](double rho) {
    const Vec3 m(rho * outward.x(), rho * outward.y(), a + height(rho));
    const Vec3 r = reflect(m.normalized(), slope(rho), outward);
    const double rs = r.x() * outward.x() + r.y() * outward.y();
    return rs * (point.z() - m.z()) - r.z() * (distance - rho);
  };
  const double step = profile_.rim_radius_m / kProjectionScan;
  double lo = 1e-9, f_lo = miss(lo);
  for (int i = 1; i <= kProjectionScan; ++i) {
    const double hi = i * step;
    const double f_hi = miss(hi);
    if ((f_lo > 0.0) != (f_hi > 0.0)) {
      double l = lo, h = hi;
      for (int k = 0; k < kBisections; ++k) {
        const double mid = 0.5 * (l + h);
        ((miss(mid) > 0.0) == (f_lo > 0.0) ? l : h) = mid;
      }
      const double rho = 0.5 * (l + h);
      const Vec3 m(rho * outward.x(), rho * outward.y(), a + height(rho));
      // The point must lie ahead along the reflected ray.
      const Vec3 r = reflect(m.normalized(), slope(rho), outward);
      if (r.dot(point - m) <= 0.0) return std::nullopt;
      const Vec2 x(-m.y() / m.z(), -m.x() / m.z());
      return principal_px_ + focal_px_ * x * (1.0 + profile_.lens_k1 * x.squaredNorm());
    }
    lo = hi;
    f_lo = f_hi;
  }
  return std::nullopt;
}

}  // namespace ballsight
