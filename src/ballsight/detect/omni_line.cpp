#include "ballsight/detect/omni_line.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

namespace {

constexpr double kVertexWindowDeg = 15.0;  // the parabola is fitted to the points this near
constexpr int kMinVertexPoints = 7;
// A line's image bends away from the centre: this much farther kVertexWindowDeg off the normal
// (MinhoTeam's lines at 2-2.5 m: 2 px; a ring: none).
constexpr double kMinBendPx = 1.0;
constexpr double kFaintWindowDeg = 10.0;  // a point's neighbours, for its relative contrast
constexpr double kMinRelativeContrast = 0.6;

struct Ray {
  double theta_deg = 0.0;
  std::vector<RayPeak> peaks;
};

// The peak nearest `expected` within `tolerance`, if any.
const RayPeak* nearest_peak(const Ray& ray, double expected, double tolerance) {
  const RayPeak* best = nullptr;
  for (const RayPeak& p : ray.peaks) {
    if (std::abs(p.radius_px - expected) <= tolerance &&
        (!best || std::abs(p.radius_px - expected) < std::abs(best->radius_px - expected)))
      best = &p;
  }
  return best;
}

// The line followed from `radius` on ray `start` in direction `step` (+1 or -1), at most `limit`
// rays: each ray's peak nearest the course extrapolated from the last two points found. Where
// the line is lost (max_gap rays in a row), the point before is beside what hides it: dropped.
void follow(const std::vector<Ray>& rays, std::size_t start, double radius, int step,
            std::size_t limit, const LineSearchOptions& options, std::vector<LinePoint>& points) {
  double last = radius;
  double slope = 0.0;  // px per ray
  int gap = 0;
  const std::size_t before = points.size();
  for (std::size_t n = 1; n <= limit && gap < options.max_gap; ++n) {
    const auto i = static_cast<std::ptrdiff_t>(start) + step * static_cast<std::ptrdiff_t>(n);
    if (i < 0 || i >= static_cast<std::ptrdiff_t>(rays.size())) break;
    const Ray& ray = rays[static_cast<std::size_t>(i)];
    const RayPeak* p = nearest_peak(ray, last + slope * (gap + 1), options.tolerance_px);
    if (!p) {
      ++gap;
      continue;
    }
    slope = (p->radius_px - last) / (gap + 1);
    last = p->radius_px;
    gap = 0;
    points.push_back({ray.theta_deg, p->radius_px, 0.0, p->height});
  }
  if (gap >= options.max_gap && points.size() > before) points.pop_back();
}

// The points the line shows whole: at least kMinRelativeContrast of the median contrast of
// their neighbours, and not beside a stretch where it is hidden (an occluder's edge shifts the
// peak). `points` by image angle, `step_deg` apart where nothing hides the line.
std::vector<LinePoint> shown_whole(const std::vector<LinePoint>& points, double step_deg) {
  std::vector<LinePoint> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const LinePoint& p = points[i];
    std::vector<double> around;
    for (const LinePoint& q : points)
      if (std::abs(q.theta_deg - p.theta_deg) <= kFaintWindowDeg) around.push_back(q.contrast);
    const bool gap_before = i > 0 && p.theta_deg - points[i - 1].theta_deg > 1.5 * step_deg;
    const bool gap_after =
        i + 1 < points.size() && points[i + 1].theta_deg - p.theta_deg > 1.5 * step_deg;
    if (p.contrast >= kMinRelativeContrast * median(around) && !gap_before && !gap_after)
      kept.push_back(p);
  }
  return kept;
}

// Every point of the curve through `peak` on ray `start`, both ways, at most `limit` rays.
std::vector<LinePoint> curve_through(const std::vector<Ray>& rays, std::size_t start,
                                     const RayPeak& peak, std::size_t limit,
                                     const LineSearchOptions& options) {
  std::vector<LinePoint> points{{rays[start].theta_deg, peak.radius_px, 0.0, peak.height}};
  follow(rays, start, peak.radius_px, -1, limit, options, points);
  follow(rays, start, peak.radius_px, +1, limit, options, points);
  std::sort(points.begin(), points.end(),
            [](const LinePoint& a, const LinePoint& b) { return a.theta_deg < b.theta_deg; });
  return points;
}

struct Candidate {
  std::size_t ray = 0;
  RayPeak peak;
  std::size_t count = 0;  // points of its curve over +-kVertexWindowDeg
};

// The line through `peak` on ray `start`: its points and the vertex of its image. Throws
// InputError when the curve is too short around its nearest point or does not bend like a line.
LineSearch line_through(const std::vector<Ray>& rays, std::size_t start, const RayPeak& peak,
                        const LineSearchOptions& options) {
  const std::vector<LinePoint> points =
      shown_whole(curve_through(rays, start, peak, rays.size(), options), options.step_deg);
  require(static_cast<int>(points.size()) >= kMinVertexPoints, "image",
          "shows the line too briefly around its nearest point to find its normal");
  const LinePoint& nearest = *std::min_element(
      points.begin(), points.end(),
      [](const LinePoint& a, const LinePoint& b) { return a.radius_px < b.radius_px; });

  // The vertex: r = c0 + c1 x + c2 x^2 over the points within the window of the nearest ray.
  std::vector<const LinePoint*> near;
  for (const LinePoint& p : points)
    if (std::abs(p.theta_deg - nearest.theta_deg) <= kVertexWindowDeg) near.push_back(&p);
  const bool both_sides = near.front()->theta_deg < nearest.theta_deg - 0.5 * kVertexWindowDeg &&
                          near.back()->theta_deg > nearest.theta_deg + 0.5 * kVertexWindowDeg;
  require(static_cast<int>(near.size()) >= kMinVertexPoints && both_sides, "image",
          "shows the line too briefly around its nearest point to find its normal");
  Eigen::MatrixX3d a(static_cast<Eigen::Index>(near.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(near.size()));
  for (std::size_t i = 0; i < near.size(); ++i) {
    const double x = near[i]->theta_deg - nearest.theta_deg;
    a.row(static_cast<Eigen::Index>(i)) << 1.0, x, x * x;
    b(static_cast<Eigen::Index>(i)) = near[i]->radius_px;
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
  const double normal_deg = nearest.theta_deg - c(1) / (2.0 * c(2));
  require(c(2) * kVertexWindowDeg * kVertexWindowDeg >= kMinBendPx &&
              std::abs(normal_deg - nearest.theta_deg) <= kVertexWindowDeg &&
              std::abs(wrap_deg_180(normal_deg - options.toward_deg)) <= options.window_deg,
          "image",
          "shows a bright curve near the direction given that does not bend like a straight "
          "line's image (nearest the centre within the window, farther both ways)");
  LineSearch search;
  search.normal_deg = wrap_deg_360(normal_deg);
  search.nearest_radius_px = c(0) - c(1) * c(1) / (4.0 * c(2));
  for (LinePoint p : points) {
    p.off_normal_deg = p.theta_deg - normal_deg;
    p.theta_deg = wrap_deg_360(p.theta_deg);
    if (std::abs(p.off_normal_deg) <= options.max_off_normal_deg) search.points.push_back(p);
  }
  return search;
}

}  // namespace

void LineSearchOptions::validate() const {
  require(std::isfinite(toward_deg), "toward_deg", "expected a number");
  require(std::isfinite(window_deg) && window_deg > 0.0 && window_deg <= 90.0, "window_deg",
          "expected a number in (0, 90]");
  require(std::isfinite(max_off_normal_deg) && max_off_normal_deg >= kVertexWindowDeg &&
              max_off_normal_deg < 90.0,
          "max_off_normal_deg", "expected 15 to 90 (exclusive)");
  require(std::isfinite(step_deg) && step_deg >= 0.1 && step_deg <= 5.0, "step_deg",
          "expected 0.1 to 5");
  validate_ray_radii(min_radius_px, max_radius_px);
  require(std::isfinite(tolerance_px) && tolerance_px > 0.0 && tolerance_px <= 50.0, "tolerance_px",
          "expected a number in (0, 50]");
  require(max_gap >= 1 && max_gap <= 100, "max_gap", "expected 1 to 100");
  peaks.validate();
}

LineSearch find_omni_line(const cv::Mat1b& grey, const Vec2& center,
                          const LineSearchOptions& options) {
  options.validate();
  const auto [r0, r1] = ray_span(grey, center, options.min_radius_px, options.max_radius_px);

  // Rays over toward +- (window + max off normal), the window's first and last.
  const double span = options.window_deg + options.max_off_normal_deg;
  const auto half = static_cast<int>(std::floor(span / options.step_deg));
  std::vector<Ray> rays;
  for (int k = -half; k <= half; ++k) {
    const double theta = wrap_deg_360(options.toward_deg) + k * options.step_deg;
    rays.push_back({theta, ray_peaks(grey, center, theta, r0, r1, options.peaks)});
  }
  // The line: of the peaks within the window of `toward`, the one through which the longest
  // curve runs over +-kVertexWindowDeg (the nearest of equals); a speck or a strut's edge runs
  // nowhere.
  const auto window = static_cast<std::size_t>(std::floor(options.window_deg / options.step_deg));
  const auto reach = static_cast<std::size_t>(std::ceil(kVertexWindowDeg / options.step_deg));
  std::vector<Candidate> candidates;
  for (std::size_t i = static_cast<std::size_t>(half) - window;
       i <= static_cast<std::size_t>(half) + window; ++i) {
    for (const RayPeak& peak : rays[i].peaks)
      candidates.push_back({i, peak, curve_through(rays, i, peak, reach, options).size()});
  }
  require(!candidates.empty(), "image",
          "shows no bright line within " + std::to_string(static_cast<int>(options.window_deg)) +
              " deg of the direction given; check the direction, the centre and the contrast");
  // A nearer curve that is no line (the robot's rim, a reflection) gives way to the next.
  std::stable_sort(
      candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        return x.count != y.count ? x.count > y.count : x.peak.radius_px < y.peak.radius_px;
      });
  std::optional<InputError> first_error;
  for (const Candidate& candidate : candidates) {
    try {
      return line_through(rays, candidate.ray, candidate.peak, options);
    } catch (const InputError& e) {
      if (!first_error) first_error = e;
    }
  }
  throw *first_error;
}

cv::Mat plot_omni_line(const cv::Mat1b& grey, const Vec2& center, const LineSearch& search) {
  cv::Mat plot = ray_plot_canvas(grey);
  const auto at = [&](double theta, double r) { return ray_plot_point(center, theta, r); };
  cv::line(plot, at(0.0, 0.0), at(search.normal_deg, search.nearest_radius_px), {255, 120, 0}, 1);
  for (const LinePoint& p : search.points)
    cv::circle(plot, at(p.theta_deg, p.radius_px), 2, {0, 220, 0}, cv::FILLED);
  mark_ray_plot_center(plot, center);
  return plot;
}

}  // namespace ballsight
