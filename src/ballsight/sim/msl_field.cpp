#include "ballsight/sim/msl_field.hpp"

#include <cmath>
#include <cstdint>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {

namespace {

bool in_range(double value, double lo, double hi) {
  return std::isfinite(value) && value >= lo && value <= hi;
}

void require_range(double value, double lo, double hi, const std::string& name,
                   const std::string& unit) {
  require(in_range(value, lo, hi), "field." + name,
          "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] " + unit);
}

// Cheap integer hash of a carpet cell (a 2D variant of the splitmix64 finaliser).
std::uint32_t cell_hash(std::int64_t ix, std::int64_t iy) {
  std::uint64_t h = static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(iy) * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return static_cast<std::uint32_t>(h >> 32);
}

}  // namespace

void MslFieldSpec::validate() const {
  require_range(width_m, 1.0, 100.0, "width_m", "m");
  require_range(length_m, 1.0, 100.0, "length_m", "m");
  const double small_side = std::min(width_m, length_m);
  require_range(line_width_m, 0.01, 0.5, "line_width_m", "m");
  require_range(center_circle_radius_m, line_width_m, 0.5 * small_side - line_width_m,
                "center_circle_radius_m", "m (inside the field)");
  require_range(spot_radius_m, 0.0, 0.5, "spot_radius_m", "m");
  require_range(penalty_area_width_m, line_width_m, width_m - line_width_m, "penalty_area_width_m",
                "m (narrower than the field)");
  require_range(goal_area_width_m, line_width_m, penalty_area_width_m, "goal_area_width_m",
                "m (not wider than the penalty area)");
  require_range(penalty_area_depth_m, line_width_m, 0.5 * length_m - line_width_m,
                "penalty_area_depth_m", "m (within half the field)");
  require_range(goal_area_depth_m, line_width_m, penalty_area_depth_m, "goal_area_depth_m",
                "m (not deeper than the penalty area)");
  require_range(penalty_spot_distance_m, 0.0, 0.5 * length_m, "penalty_spot_distance_m",
                "m (within half the field)");
  require_range(corner_arc_radius_m, 0.0, 0.5 * small_side, "corner_arc_radius_m", "m");
  require_range(carpet_margin_m, 0.0, 10.0, "carpet_margin_m", "m");
  require(carpet_texture_levels >= 0 && carpet_texture_levels <= 40, "field.carpet_texture_levels",
          "must be in [0, 40] grey levels");
}

MslField::MslField(const MslFieldSpec& spec) : spec_((spec.validate(), spec)) {
  const double w = spec.width_m;
  const double l = spec.length_m;
  const double h = 0.5 * spec.line_width_m;
  const double m = spec.carpet_margin_m;
  carpet_ = {-h - m, -h - m, w + h + m, l + h + m};
  const Box everywhere{-1e9, -1e9, 1e9, 1e9};

  // Touch lines, goal lines, halfway line.
  boxes_.push_back({-h, -h, h, l + h});
  boxes_.push_back({w - h, -h, w + h, l + h});
  boxes_.push_back({-h, -h, w + h, h});
  boxes_.push_back({-h, l - h, w + h, l + h});
  boxes_.push_back({-h, 0.5 * l - h, w + h, 0.5 * l + h});

  // Goal and penalty areas at both ends: two side lines and a front line each.
  for (const double goal_y : {0.0, l}) {
    const double into_field = goal_y == 0.0 ? 1.0 : -1.0;
    for (const auto& [area_width, depth] :
         {std::pair{spec.goal_area_width_m, spec.goal_area_depth_m},
          std::pair{spec.penalty_area_width_m, spec.penalty_area_depth_m}}) {
      const double xa = 0.5 * (w - area_width);
      const double xb = 0.5 * (w + area_width);
      const double front = goal_y + into_field * depth;
      const double ya = std::min(goal_y, front);
      const double yb = std::max(goal_y, front);
      boxes_.push_back({xa - h, ya - h, xa + h, yb + h});
      boxes_.push_back({xb - h, ya - h, xb + h, yb + h});
      boxes_.push_back({xa - h, front - h, xb + h, front + h});
    }
    const Vec2 penalty_spot(0.5 * w, goal_y + into_field * spec.penalty_spot_distance_m);
    rings_.push_back({penalty_spot, 0.0, spec.spot_radius_m * spec.spot_radius_m, everywhere});
  }

  const auto ring = [h](double radius) {
    const double inner = std::max(0.0, radius - h);
    return std::pair{inner * inner, (radius + h) * (radius + h)};
  };
  const auto [circle_inner2, circle_outer2] = ring(spec.center_circle_radius_m);
  rings_.push_back({spec.center_spot(), circle_inner2, circle_outer2, everywhere});
  rings_.push_back({spec.center_spot(), 0.0, spec.spot_radius_m * spec.spot_radius_m, everywhere});

  // Corner arcs: quarter rings inside the field.
  const auto [arc_inner2, arc_outer2] = ring(spec.corner_arc_radius_m);
  rings_.push_back({{0.0, 0.0}, arc_inner2, arc_outer2, {0.0, 0.0, w, l}});
  rings_.push_back({{w, 0.0}, arc_inner2, arc_outer2, {0.0, 0.0, w, l}});
  rings_.push_back({{0.0, l}, arc_inner2, arc_outer2, {0.0, 0.0, w, l}});
  rings_.push_back({{w, l}, arc_inner2, arc_outer2, {0.0, 0.0, w, l}});
}

bool MslField::on_carpet(const Vec2& p) const {
  return p.x() >= carpet_.x0 && p.x() <= carpet_.x1 && p.y() >= carpet_.y0 && p.y() <= carpet_.y1;
}

bool MslField::on_line(const Vec2& p) const {
  const double x = p.x();
  const double y = p.y();
  for (const Box& b : boxes_) {
    if (x >= b.x0 && x <= b.x1 && y >= b.y0 && y <= b.y1) return true;
  }
  for (const Ring& r : rings_) {
    if (x < r.clip.x0 || x > r.clip.x1 || y < r.clip.y0 || y > r.clip.y1) continue;
    const double d2 = (p - r.center).squaredNorm();
    if (d2 >= r.inner2 && d2 <= r.outer2) return true;
  }
  return false;
}

cv::Vec3b MslField::colour_at(const Vec2& p) const {
  if (!on_carpet(p)) return spec_.floor_bgr;
  if (on_line(p)) return spec_.line_bgr;
  // Carpet fibre texture: a hashed brightness per 2 cm cell plus faint 1 m roll stripes.
  const int levels = spec_.carpet_texture_levels;
  if (levels == 0) return spec_.carpet_bgr;
  const auto ix = static_cast<std::int64_t>(std::floor(p.x() * 50.0));
  const auto iy = static_cast<std::int64_t>(std::floor(p.y() * 50.0));
  const int half = levels / 2;
  const int grain =
      static_cast<int>(cell_hash(ix, iy) % static_cast<std::uint32_t>(2 * half + 1)) - half;
  const int stripe = (static_cast<std::int64_t>(std::floor(p.x())) & 1) != 0 ? half : -half;
  const int delta = grain + stripe;  // within [-levels, levels]
  const cv::Vec3b& c = spec_.carpet_bgr;
  return {cv::saturate_cast<uchar>(c[0] + delta), cv::saturate_cast<uchar>(c[1] + delta),
          cv::saturate_cast<uchar>(c[2] + delta)};
}

}  // namespace ballsight::sim
