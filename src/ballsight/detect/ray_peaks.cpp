#include "ballsight/detect/ray_peaks.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

namespace {

constexpr double kStepPx = 0.25;  // along a ray
constexpr int kPlotScale = 2;

double bilinear(const cv::Mat1b& grey, const Vec2& p) {
  const int x0 = static_cast<int>(std::floor(p.x())), y0 = static_cast<int>(std::floor(p.y()));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= grey.cols || y0 + 1 >= grey.rows) return 0.0;
  const double fx = p.x() - x0, fy = p.y() - y0;
  const double top = (1.0 - fx) * grey(y0, x0) + fx * grey(y0, x0 + 1);
  const double bottom = (1.0 - fx) * grey(y0 + 1, x0) + fx * grey(y0 + 1, x0 + 1);
  return (1.0 - fy) * top + fy * bottom;
}

// Sliding minimum (or maximum) over +-half samples.
std::vector<double> sliding(const std::vector<double>& v, int half, bool minimum) {
  std::vector<double> out(v.size());
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i) {
    double m = v[i];
    for (int j = std::max(0, i - half); j <= std::min(n - 1, i + half); ++j) {
      m = minimum ? std::min(m, v[j]) : std::max(m, v[j]);
    }
    out[i] = m;
  }
  return out;
}

}  // namespace

void RayPeakOptions::validate() const {
  require(std::isfinite(min_contrast) && min_contrast > 0.0, "min_contrast",
          "expected a positive number");
  require(std::isfinite(background_px) && background_px >= 1.0 && background_px <= 50.0,
          "background_px", "expected 1 to 50");
}

void validate_ray_radii(double min_radius_px, std::optional<double> max_radius_px) {
  require(std::isfinite(min_radius_px) && min_radius_px >= 0.0, "min_radius_px",
          "expected a number >= 0");
  require(!max_radius_px || (std::isfinite(*max_radius_px) && *max_radius_px > min_radius_px + 2),
          "max_radius_px", "expected a number above min_radius_px + 2");
}

RaySpan ray_span(const cv::Mat1b& grey, const Vec2& center, double min_radius_px,
                 std::optional<double> max_radius_px) {
  require(!grey.empty(), "image", "is empty");
  require(center.x() >= 0.0 && center.y() >= 0.0 && center.x() <= grey.cols - 1 &&
              center.y() <= grey.rows - 1,
          "center", "expected a point inside the image");
  const double inside =
      std::min({center.x(), center.y(), grey.cols - 1 - center.x(), grey.rows - 1 - center.y()});
  const RaySpan span{min_radius_px, max_radius_px ? *max_radius_px : inside};
  require(span.r1 > span.r0 + 2.0, "image",
          "leaves no room between the search radii around the centre");
  return span;
}

std::vector<RayPeak> ray_peaks(const cv::Mat1b& grey, const Vec2& center, double theta_deg,
                               double r0, double r1, const RayPeakOptions& options) {
  std::vector<double> profile;
  const auto samples = static_cast<std::size_t>(std::max(0.0, std::floor((r1 - r0) / kStepPx) + 1));
  for (std::size_t i = 0; i < samples; ++i) {
    const double r = r0 + static_cast<double>(i) * kStepPx;
    profile.push_back(bilinear(grey, pixel_from_image_polar({theta_deg, r}, center)));
  }
  const int half = static_cast<int>(std::lround(options.background_px / kStepPx));
  const std::vector<double> opening = sliding(sliding(profile, half, true), half, false);
  std::vector<double> t(profile.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = profile[i] - opening[i];
  std::vector<RayPeak> peaks;
  const int n = static_cast<int>(t.size());
  for (int i = 1; i + 1 < n; ++i) {
    if (t[i] < options.min_contrast || t[i] < t[i - 1] || t[i] <= t[i + 1]) continue;
    const double level = 0.5 * t[i];
    int a = i, b = i;
    while (a > 0 && t[a - 1] >= level) --a;
    while (b + 1 < n && t[b + 1] >= level) ++b;
    double weight = 0.0, moment = 0.0;
    for (int j = a; j <= b; ++j) {
      weight += t[j] - level;
      moment += (t[j] - level) * (r0 + j * kStepPx);
    }
    if (weight > 0.0) peaks.push_back({moment / weight, t[i]});
    i = b;
  }
  return peaks;
}

cv::Mat ray_plot_canvas(const cv::Mat1b& grey) {
  cv::Mat plot;
  cv::cvtColor(grey, plot, cv::COLOR_GRAY2BGR);
  cv::resize(plot, plot, {}, kPlotScale, kPlotScale, cv::INTER_NEAREST);
  return plot;
}

cv::Point ray_plot_point(const Vec2& center, double theta_deg, double radius_px) {
  const Vec2 p = pixel_from_image_polar({theta_deg, radius_px}, center);
  return {static_cast<int>(std::lround(kPlotScale * (p.x() + 0.5))),
          static_cast<int>(std::lround(kPlotScale * (p.y() + 0.5)))};
}

void mark_ray_plot_center(cv::Mat& plot, const Vec2& center) {
  cv::drawMarker(plot, ray_plot_point(center, 0.0, 0.0), {255, 200, 0}, cv::MARKER_CROSS, 16, 2);
}

}  // namespace ballsight
