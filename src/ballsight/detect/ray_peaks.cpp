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

// The bar widths tried, px: from 1 px, each about a third wider, up to `max_width_px`.
std::vector<double> bar_widths(double max_width_px) {
  std::vector<double> widths;
  for (double w = 1.0; w <= max_width_px; w = std::max(w + 0.5, 1.3 * w)) widths.push_back(w);
  return widths;
}

// A profile's means over index ranges, from its prefix sums.
class RangeMeans {
 public:
  explicit RangeMeans(const std::vector<double>& v) : sum_(v.size() + 1, 0.0) {
    for (std::size_t i = 0; i < v.size(); ++i) sum_[i + 1] = sum_[i] + v[i];
  }
  int size() const { return static_cast<int>(sum_.size()) - 1; }
  // The mean of samples a..b (inclusive, inside the profile).
  double mean(int a, int b) const { return (sum_[b + 1] - sum_[a]) / (b - a + 1); }

 private:
  std::vector<double> sum_;
};

// The best bar centred at each sample: its contrast (0 where none fits), half-width and the
// background level of its sides.
struct Bar {
  double contrast = 0.0;
  int half = 0;                    // samples either side of the centre
  double left = 0.0, right = 0.0;  // the sides' means
  int side = 0;                    // samples in each side
};

std::vector<Bar> best_bars(const RangeMeans& means, double max_width_px) {
  const int n = means.size();
  std::vector<Bar> bars(static_cast<std::size_t>(n));
  for (const double w : bar_widths(max_width_px)) {
    const int half = static_cast<int>(std::lround(0.5 * w / kStepPx));
    const int side = static_cast<int>(std::lround(std::clamp(0.5 * w, 2.0, 6.0) / kStepPx));
    for (int i = half + side; i + half + side < n; ++i) {
      const double inside = means.mean(i - half, i + half);
      const double left = means.mean(i - half - side, i - half - 1);
      const double right = means.mean(i + half + 1, i + half + side);
      const double contrast = inside - std::max(left, right);
      Bar& best = bars[static_cast<std::size_t>(i)];
      if (contrast > best.contrast) best = {contrast, half, left, right, side};
    }
  }
  return bars;
}

// The bar's centre: the centroid of the grey levels above the line between its sides' means,
// over the bar and one pixel either side.
double bar_centre(const std::vector<double>& profile, int i, const Bar& bar, double r0) {
  const int margin = static_cast<int>(std::lround(1.0 / kStepPx));
  const int a = std::max(0, i - bar.half - margin);
  const int b = std::min(static_cast<int>(profile.size()) - 1, i + bar.half + margin);
  const double span = 2.0 * bar.half + bar.side + 1.0;  // between the sides' centres
  double weight = 0.0, moment = 0.0;
  for (int j = a; j <= b; ++j) {
    const double t = (j - (i - bar.half - 0.5 * (bar.side + 1))) / span;
    const double excess =
        profile[static_cast<std::size_t>(j)] - ((1.0 - t) * bar.left + t * bar.right);
    if (excess <= 0.0) continue;
    weight += excess;
    moment += excess * (r0 + j * kStepPx);
  }
  return weight > 0.0 ? moment / weight : r0 + i * kStepPx;
}

}  // namespace

void RayPeakOptions::validate() const {
  require(std::isfinite(min_contrast) && min_contrast > 0.0, "min_contrast",
          "expected a positive number");
  require(std::isfinite(max_width_px) && max_width_px >= 1.0 && max_width_px <= 200.0,
          "max_width_px", "expected 1 to 200");
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
  const std::vector<Bar> bars = best_bars(RangeMeans(profile), options.max_width_px);
  std::vector<RayPeak> peaks;
  const int n = static_cast<int>(bars.size());
  for (int i = 0; i < n; ++i) {
    const Bar& bar = bars[static_cast<std::size_t>(i)];
    if (bar.contrast < options.min_contrast) continue;
    // The highest within half its width (the first of equals): one line, not its edges.
    bool highest = true;
    for (int j = std::max(0, i - bar.half); j <= std::min(n - 1, i + bar.half) && highest; ++j) {
      const double other = bars[static_cast<std::size_t>(j)].contrast;
      highest = j < i ? other < bar.contrast : other <= bar.contrast;
    }
    if (!highest) continue;
    peaks.push_back({bar_centre(profile, i, bar, r0), bar.contrast, 2.0 * bar.half * kStepPx});
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
