#include "ballsight/detect/omni_rings.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/statistics.hpp"
#include "ballsight/detect/ray_peaks.hpp"

namespace ballsight {

namespace {

constexpr double kFollowWindowDeg = 10.0;   // a ring's course: the median of its neighbours
constexpr double kMinRelativeHeight = 0.6;  // of the neighbours' peaks: else partly hidden

// The rings' radii where the peaks of all directions gather: the first `rings` radii (from the
// centre out) with peaks within +-tolerance/2 in at least min_support of the directions.
std::vector<double> ring_seeds(const std::vector<std::vector<RayPeak>>& peaks, double r0, double r1,
                               const RingSearchOptions& options) {
  const int bins = static_cast<int>(std::ceil(r1 - r0)) + 1;
  std::vector<double> support(bins, 0.0);
  for (const std::vector<RayPeak>& ray : peaks) {
    std::vector<bool> seen(bins, false);
    for (const RayPeak& peak : ray) {
      const double p = peak.radius_px;
      const int lo = std::max(0, static_cast<int>(std::ceil(p - r0 - 0.5 * options.tolerance_px)));
      const int hi =
          std::min(bins - 1, static_cast<int>(std::floor(p - r0 + 0.5 * options.tolerance_px)));
      for (int b = lo; b <= hi; ++b) seen[b] = true;
    }
    for (int b = 0; b < bins; ++b) support[b] += seen[b] ? 1.0 : 0.0;
  }
  const double needed = options.min_support * static_cast<double>(peaks.size());
  std::vector<double> seeds;
  for (int b = 0; b < bins && seeds.size() < options.rings; ++b) {
    const bool mode = support[b] >= needed && (b == 0 || support[b] >= support[b - 1]) &&
                      (b + 1 == bins || support[b] > support[b + 1]);
    const double radius = r0 + b;
    if (!mode || (!seeds.empty() && radius - seeds.back() <= options.tolerance_px)) continue;
    std::vector<double> near;
    for (const std::vector<RayPeak>& ray : peaks) {
      for (const RayPeak& p : ray) {
        if (std::abs(p.radius_px - radius) <= options.tolerance_px) near.push_back(p.radius_px);
      }
    }
    seeds.push_back(median(near));
  }
  return seeds;
}

// The one peak within `tolerance` of `expected`, or why there is none.
std::pair<std::optional<RayPeak>, RingMiss> match(const std::vector<RayPeak>& peaks,
                                                  double expected, double tolerance) {
  std::optional<RayPeak> found;
  for (const RayPeak& p : peaks) {
    if (std::abs(p.radius_px - expected) > tolerance) continue;
    if (found) return {std::nullopt, RingMiss::kAmbiguous};
    found = p;
  }
  return {found, found ? RingMiss::kNone : RingMiss::kHidden};
}

double angular_gap_deg(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

}  // namespace

void RingSearchOptions::validate() const {
  require(rings >= 1 && rings <= 64, "rings", "expected 1 to 64");
  require(directions >= 8 && directions <= 3600, "directions", "expected 8 to 3600");
  validate_ray_radii(min_radius_px, max_radius_px);
  peaks().validate();
  require(std::isfinite(tolerance_px) && tolerance_px > 0.0 && tolerance_px <= 50.0, "tolerance_px",
          "expected a number in (0, 50]");
  require(std::isfinite(min_support) && min_support > 0.0 && min_support <= 1.0, "min_support",
          "expected a number in (0, 1]");
}

RingSearch find_omni_rings(const cv::Mat1b& grey, const Vec2& center,
                           const RingSearchOptions& options,
                           std::span<const double> directions_deg) {
  options.validate();
  const auto [r0, r1] = ray_span(grey, center, options.min_radius_px, options.max_radius_px);
  std::vector<double> thetas(directions_deg.begin(), directions_deg.end());
  if (thetas.empty()) {
    for (int i = 0; i < options.directions; ++i) thetas.push_back(360.0 * i / options.directions);
  }
  std::vector<std::vector<RayPeak>> peaks;
  for (const double theta : thetas)
    peaks.push_back(ray_peaks(grey, center, theta, r0, r1, options.peaks()));
  const std::vector<double> seeds = ring_seeds(peaks, r0, r1, options);
  require(seeds.size() == options.rings, "image",
          "shows " + std::to_string(seeds.size()) + " rings in at least " +
              std::to_string(static_cast<int>(std::lround(100.0 * options.min_support))) +
              " % of the directions, expected " + std::to_string(options.rings) +
              "; check the centre, the number of distances and the contrast");

  RingSearch search;
  search.directions.resize(thetas.size());
  for (std::size_t d = 0; d < thetas.size(); ++d) {
    search.directions[d].theta_deg = thetas[d];
    search.directions[d].radius_px.assign(options.rings, std::nullopt);
    search.directions[d].miss.assign(options.rings, RingMiss::kHidden);
  }
  for (std::size_t k = 0; k < options.rings; ++k) {
    // First around the ring's radius, then around its course (eccentric rings of a mirror off
    // the image centre), which the neighbours' first matches give; a peak much lower than the
    // neighbours' is a ring partly hidden (at a strut's edge), its centre biased: rejected.
    std::vector<std::optional<RayPeak>> first(thetas.size());
    for (std::size_t d = 0; d < thetas.size(); ++d) {
      first[d] = match(peaks[d], seeds[k], options.tolerance_px).first;
    }
    std::vector<double> found;
    for (std::size_t d = 0; d < thetas.size(); ++d) {
      std::vector<double> radii, heights;
      for (std::size_t e = 0; e < thetas.size(); ++e) {
        if (first[e] && angular_gap_deg(thetas[d], thetas[e]) <= kFollowWindowDeg) {
          radii.push_back(first[e]->radius_px);
          heights.push_back(first[e]->height);
        }
      }
      const double course = radii.size() >= 3 ? median(radii) : seeds[k];
      auto [peak, miss] = match(peaks[d], course, 0.5 * options.tolerance_px);
      if (peak && radii.size() >= 3 && peak->height < kMinRelativeHeight * median(heights)) {
        peak.reset();
        miss = RingMiss::kHidden;
      }
      const std::optional<double> radius =
          peak ? std::optional<double>(peak->radius_px) : std::nullopt;
      search.directions[d].radius_px[k] = radius;
      search.directions[d].miss[k] = miss;
      if (radius) found.push_back(*radius);
      search.hidden += miss == RingMiss::kHidden ? 1 : 0;
      search.ambiguous += miss == RingMiss::kAmbiguous ? 1 : 0;
    }
    search.ring_radius_px.push_back(found.empty() ? seeds[k] : median(found));
  }
  return search;
}

cv::Mat plot_omni_rings(const cv::Mat1b& grey, const Vec2& center, const RingSearch& search) {
  cv::Mat plot = ray_plot_canvas(grey);
  const auto at = [&](double theta, double r) { return ray_plot_point(center, theta, r); };
  for (const RingDirection& d : search.directions) {
    for (std::size_t k = 0; k < d.radius_px.size(); ++k) {
      if (d.radius_px[k]) {
        cv::circle(plot, at(d.theta_deg, *d.radius_px[k]), 2, {0, 220, 0}, cv::FILLED);
      } else {
        const cv::Scalar colour =
            d.miss[k] == RingMiss::kAmbiguous ? cv::Scalar(0, 160, 255) : cv::Scalar(0, 0, 255);
        cv::drawMarker(plot, at(d.theta_deg, search.ring_radius_px[k]), colour, cv::MARKER_CROSS, 6,
                       1);
      }
    }
  }
  mark_ray_plot_center(plot, center);
  return plot;
}

}  // namespace ballsight
