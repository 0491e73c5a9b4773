#include "ballsight/sim/tennis_court.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/enum_names.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

/// Fraction of the interval [c - h, c + h] inside [lo, hi]; a point test when h is 0.
double interval_coverage(double c, double h, double lo, double hi) {
  if (h <= 0.0) return (c >= lo && c <= hi) ? 1.0 : 0.0;
  const double overlap = std::min(c + h, hi) - std::max(c - h, lo);
  return std::clamp(overlap / (2.0 * h), 0.0, 1.0);
}

double rect_coverage(const GroundRect& r, const Vec2& p, const Vec2& half) {
  const double cx = interval_coverage(p.x(), half.x(), r.x_min, r.x_max);
  if (cx == 0.0) return 0.0;
  return cx * interval_coverage(p.y(), half.y(), r.y_min, r.y_max);
}

cv::Vec3f to_float(const cv::Vec3b& c) {
  return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

constexpr EnumNames<CourtSurface, 5> kSurfaces{{{CourtSurface::green, "green"},
                                                {CourtSurface::blue, "blue"},
                                                {CourtSurface::red, "red"},
                                                {CourtSurface::concrete, "concrete"},
                                                {CourtSurface::wood, "wood"}}};

}  // namespace

std::string_view court_surface_name(CourtSurface surface) {
  return enum_name(kSurfaces, surface);
}

std::optional<CourtSurface> court_surface_named(std::string_view name) {
  return enum_named(kSurfaces, name);
}

void set_court_surface(TennisCourtSpec& court, CourtSurface surface) {
  const TennisCourtSpec plain;
  court.reference_ball_bgr = surface == CourtSurface::red || surface == CourtSurface::wood
                                 ? kVioletBgr
                                 : plain.reference_ball_bgr;
  court.robot_back_marker_bgr =
      surface == CourtSurface::blue ? kVioletBgr : plain.robot_back_marker_bgr;
  switch (surface) {
    case CourtSurface::green:
      court.court_bgr = plain.court_bgr, court.surround_bgr = plain.surround_bgr;
      return;
    case CourtSurface::blue:
      court.court_bgr = {150, 100, 45}, court.surround_bgr = plain.surround_bgr;
      return;
    case CourtSurface::red:
      court.court_bgr = {55, 65, 160}, court.surround_bgr = plain.surround_bgr;
      return;
    case CourtSurface::concrete:
      court.court_bgr = {140, 144, 146}, court.surround_bgr = {118, 122, 125};
      return;
    case CourtSurface::wood:  // light oak, a darker stained wood around it
      court.court_bgr = {100, 150, 195}, court.surround_bgr = {60, 95, 135};
      return;
  }
}

void TennisCourtSpec::validate() const {
  require(positive(length_m), "court.length_m", "must be positive");
  require(positive(doubles_width_m), "court.doubles_width_m", "must be positive");
  require(positive(singles_width_m) && singles_width_m < doubles_width_m, "court.singles_width_m",
          "must be positive and less than doubles_width_m");
  require(positive(service_line_from_net_m) && service_line_from_net_m < length_m / 2.0,
          "court.service_line_from_net_m", "must be positive and less than half the length");
  require(positive(line_width_m) && line_width_m < 0.5, "court.line_width_m",
          "must be in (0, 0.5) m");
  require(std::isfinite(centre_mark_length_m) && centre_mark_length_m >= 0.0 &&
              centre_mark_length_m < service_line_from_net_m,
          "court.centre_mark_length_m", "must be in [0, service_line_from_net_m)");
  require(std::isfinite(surround_length_m) && surround_length_m >= length_m,
          "court.surround_length_m", "must be at least the court length");
  require(std::isfinite(surround_width_m) && surround_width_m >= doubles_width_m,
          "court.surround_width_m", "must be at least the doubles width");
  require(positive(net.post_radius_m) && net.post_radius_m <= 0.075, "court.net.post_radius_m",
          "must be in (0, 0.075] m");
  require(
      std::isfinite(net.post_outside_doubles_m) && net.post_outside_doubles_m > net.post_radius_m,
      "court.net.post_outside_doubles_m", "must exceed the post radius (posts off the court)");
  require(doubles_width_m / 2.0 + net.post_outside_doubles_m + net.post_radius_m <=
              surround_width_m / 2.0,
          "court.net.post_outside_doubles_m", "puts the posts outside the run-off area");
  require(positive(net.post_height_m) && net.post_height_m < 3.0, "court.net.post_height_m",
          "must be in (0, 3) m");
  require(positive(net.centre_height_m) && net.centre_height_m <= net.post_height_m,
          "court.net.centre_height_m", "must be in (0, post_height_m]");
  require(positive(net.band_depth_m) && net.band_depth_m < net.centre_height_m,
          "court.net.band_depth_m", "must be in (0, centre_height_m)");
}

GroundRect TennisCourtSpec::court_rect() const {
  return {-length_m / 2.0, length_m / 2.0, -doubles_width_m / 2.0, doubles_width_m / 2.0};
}

GroundRect TennisCourtSpec::surround_rect() const {
  return {-surround_length_m / 2.0, surround_length_m / 2.0, -surround_width_m / 2.0,
          surround_width_m / 2.0};
}

std::vector<GroundRect> TennisCourtSpec::line_rects() const {
  const double hx = length_m / 2.0, hd = doubles_width_m / 2.0, hs = singles_width_m / 2.0;
  const double w = line_width_m, s = service_line_from_net_m;
  std::vector<GroundRect> lines;
  for (const double side : {-1.0, 1.0}) {
    // Baseline, doubles sideline, singles sideline, service line, centre mark on this side.
    lines.push_back({side > 0 ? hx - w : -hx, side > 0 ? hx : -hx + w, -hd, hd});
    lines.push_back({-hx, hx, side > 0 ? hd - w : -hd, side > 0 ? hd : -hd + w});
    lines.push_back({-hx, hx, side > 0 ? hs - w : -hs, side > 0 ? hs : -hs + w});
    lines.push_back({side > 0 ? s - w : -s, side > 0 ? s : -s + w, -hs, hs});
    const double mark_inner = hx - w - centre_mark_length_m;
    lines.push_back(
        {side > 0 ? mark_inner : -hx + w, side > 0 ? hx - w : -mark_inner, -w / 2.0, w / 2.0});
  }
  lines.push_back({-s, s, -w / 2.0, w / 2.0});  // centre service line, both halves
  return lines;
}

cv::Vec3f floor_albedo(const TennisCourtSpec& court, const std::vector<GroundRect>& lines,
                       const Vec2& p_in_field, const Vec2& half_footprint_m) {
  // Nested areas: lines inside the court inside the run-off inside the ground, so each colour's
  // share is its area's coverage minus that of the area painted over it.
  const double surround = rect_coverage(court.surround_rect(), p_in_field, half_footprint_m);
  const double inside =
      surround > 0.0 ? rect_coverage(court.court_rect(), p_in_field, half_footprint_m) : 0.0;
  double line = 0.0;
  if (inside > 0.0) {
    for (const GroundRect& r : lines) line += rect_coverage(r, p_in_field, half_footprint_m);
    line = std::min(line, inside);  // crossing lines overlap
  }
  const auto share = [](double v) { return static_cast<float>(v); };
  return to_float(court.ground_bgr) * share(1.0 - surround) +
         to_float(court.surround_bgr) * share(surround - inside) +
         to_float(court.court_bgr) * share(inside - line) + to_float(court.line_bgr) * share(line);
}

}  // namespace ballsight::sim
