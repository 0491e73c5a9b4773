#include "ballsight/detect/ray_peaks.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/conventions.hpp"

namespace ballsight {

namespace {

constexpr double kStepPx = 0.25;  // along a ray

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

}  // namespace ballsight
