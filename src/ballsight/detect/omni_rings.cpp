#include "ballsight/detect/omni_rings.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

namespace {

constexpr double kFollowWindowDeg = 10.0;   // a ring's local course: its neighbours' departures
constexpr double kMinRelativeHeight = 0.6;  // of the neighbours' lines: else partly hidden
constexpr double kMaxSlopeGrowth = 1.25;    // px per metre between rings, against the ring before
constexpr int kFollowRounds = 3;            // line matched, curve refitted

// The image direction of image angle theta, a unit vector in pixels.
Vec2 direction_of(double theta_deg) {
  return pixel_from_image_polar({theta_deg, 1.0}, Vec2::Zero());
}

// Where the lines of all directions gather: per 1 px radius bin from r0, the directions with a
// line within +-tolerance/2 of it once the rings' centre is moved by `shift` (a line at radius r
// along u lies at r - shift.u from the moved centre, to first order).
std::vector<double> support(const std::vector<std::vector<RayPeak>>& peaks,
                            const std::vector<Vec2>& units, const Vec2& shift, double r0, int bins,
                            double tolerance) {
  std::vector<double> count(static_cast<std::size_t>(bins), 0.0);
  std::vector<int> last(static_cast<std::size_t>(bins), -1);
  for (std::size_t d = 0; d < peaks.size(); ++d) {
    const double moved = shift.dot(units[d]);
    for (const RayPeak& peak : peaks[d]) {
      const double p = peak.radius_px - moved - r0;
      const int lo = std::max(0, static_cast<int>(std::ceil(p - 0.5 * tolerance)));
      const int hi = std::min(bins - 1, static_cast<int>(std::floor(p + 0.5 * tolerance)));
      for (int b = lo; b <= hi; ++b) {
        if (last[static_cast<std::size_t>(b)] == static_cast<int>(d)) continue;
        last[static_cast<std::size_t>(b)] = static_cast<int>(d);
        count[static_cast<std::size_t>(b)] += 1.0;
      }
    }
  }
  return count;
}

// The rings' centre relative to the given one, to the pixel: where the lines gather most sharply
// (the sum of the squared supports is largest).
Vec2 decentring(const std::vector<std::vector<RayPeak>>& peaks, const std::vector<Vec2>& units,
                double r0, int bins, const RingSearchOptions& options) {
  const int reach = static_cast<int>(std::floor(options.max_decentring_px));
  Vec2 best = Vec2::Zero();
  double sharpest = -1.0;
  for (int y = -reach; y <= reach; ++y) {
    for (int x = -reach; x <= reach; ++x) {
      const Vec2 shift(x, y);
      if (shift.norm() > options.max_decentring_px) continue;
      double sharpness = 0.0;
      for (const double s : support(peaks, units, shift, r0, bins, options.tolerance_px))
        sharpness += s * s;
      // Ties go to the smaller shift (none, where nothing tells the shifts apart).
      if (sharpness > sharpest || (sharpness == sharpest && shift.norm() < best.norm())) {
        sharpest = sharpness;
        best = shift;
      }
    }
  }
  return best;
}

struct Mode {
  double radius_px = 0.0;  // from the moved centre
  double support = 0.0;    // directions
};

// The radii (from the moved centre) where the lines of at least min_support of the directions
// gather: the local maxima of the support, one per tolerance.
std::vector<Mode> modes(const std::vector<std::vector<RayPeak>>& peaks,
                        const std::vector<Vec2>& units, const Vec2& shift, double r0, int bins,
                        const RingSearchOptions& options) {
  const std::vector<double> s = support(peaks, units, shift, r0, bins, options.tolerance_px);
  const double needed = options.min_support * static_cast<double>(peaks.size());
  std::vector<Mode> out;
  for (int b = 0; b < bins; ++b) {
    const auto i = static_cast<std::size_t>(b);
    const bool mode =
        s[i] >= needed && (b == 0 || s[i] >= s[i - 1]) && (b + 1 == bins || s[i] > s[i + 1]);
    if (!mode) continue;
    int top = b;  // the flat top's first bin: the mode is its middle
    while (top > 0 && s[static_cast<std::size_t>(top - 1)] == s[i]) --top;
    const double radius = r0 + 0.5 * (top + b);
    if (!out.empty() && radius - out.back().radius_px <= options.tolerance_px) {
      if (s[i] > out.back().support) out.back() = {radius, s[i]};
      continue;
    }
    out.push_back({radius, s[i]});
  }
  for (Mode& m : out) {  // the median of the lines near it
    std::vector<double> near;
    for (std::size_t d = 0; d < peaks.size(); ++d) {
      for (const RayPeak& p : peaks[d]) {
        const double r = p.radius_px - shift.dot(units[d]);
        if (std::abs(r - m.radius_px) <= options.tolerance_px) near.push_back(r);
      }
    }
    m.radius_px = median(near);
  }
  return out;
}

// Of the modes (by radius), one per distance in order, the most support in all, where each
// ring's radius grows per metre no faster than kMaxSlopeGrowth times the growth before it; the
// modes' indices, or as many as such a chain can have when there are fewer.
std::vector<std::size_t> ring_chain(const std::vector<Mode>& m,
                                    const std::vector<double>& distances_m, double tolerance) {
  const std::size_t count = m.size(), rings = distances_m.size();
  constexpr double kNone = -1.0;
  // value[i][j]: the most support of a chain of the current length whose last two are i then j
  // (i == j for a chain of one), chains[i][j] that chain.
  std::vector<std::vector<double>> value(count, std::vector<double>(count, kNone));
  std::vector<std::vector<std::vector<std::size_t>>> chains(
      count, std::vector<std::vector<std::size_t>>(count));
  for (std::size_t j = 0; j < count; ++j) {
    value[j][j] = m[j].support;
    chains[j][j] = {j};
  }
  std::vector<std::size_t> longest =
      count > 0 ? std::vector<std::size_t>{0} : std::vector<std::size_t>{};
  for (std::size_t k = 1; k < rings; ++k) {
    std::vector<std::vector<double>> next(count, std::vector<double>(count, kNone));
    std::vector<std::vector<std::vector<std::size_t>>> next_chains(
        count, std::vector<std::vector<std::size_t>>(count));
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t j = 0; j < count; ++j) {
        if (value[i][j] == kNone) continue;
        const double slope =
            i == j ? std::numeric_limits<double>::infinity()
                   : (m[j].radius_px - m[i].radius_px) / (distances_m[k - 1] - distances_m[k - 2]);
        for (std::size_t l = j + 1; l < count; ++l) {
          const double rise = m[l].radius_px - m[j].radius_px;
          if (rise <= tolerance) continue;
          if (rise / (distances_m[k] - distances_m[k - 1]) > kMaxSlopeGrowth * slope) continue;
          const double v = value[i][j] + m[l].support;
          if (v <= next[j][l]) continue;
          next[j][l] = v;
          next_chains[j][l] = chains[i][j];
          next_chains[j][l].push_back(l);
        }
      }
    }
    bool any = false;
    for (std::size_t j = 0; j < count; ++j)
      for (std::size_t l = 0; l < count; ++l)
        if (next[j][l] != kNone) {
          any = true;
          longest = next_chains[j][l];
        }
    if (!any) return longest;
    value = std::move(next);
    chains = std::move(next_chains);
  }
  std::vector<std::size_t> best;
  double most = kNone;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < count; ++j)
      if (value[i][j] > most) {
        most = value[i][j];
        best = chains[i][j];
      }
  return best;
}

std::array<double, 5> basis(double theta_deg) {
  const double t = rad_from_deg(theta_deg);
  return {1.0, std::cos(t), std::sin(t), std::cos(2.0 * t), std::sin(2.0 * t)};
}

// The curve through the (theta, radius) points: the Fourier terms up to the second where there
// are points enough for them (12; the first: 5; else the mean).
std::array<double, 5> fit_curve(const std::vector<double>& thetas,
                                const std::vector<double>& radii) {
  const std::size_t terms = radii.size() >= 12 ? 5 : radii.size() >= 5 ? 3 : 1;
  Eigen::MatrixXd a(static_cast<Eigen::Index>(radii.size()), static_cast<Eigen::Index>(terms));
  Eigen::VectorXd b(static_cast<Eigen::Index>(radii.size()));
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const std::array<double, 5> f = basis(thetas[i]);
    for (std::size_t t = 0; t < terms; ++t)
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(t)) = f[t];
    b(static_cast<Eigen::Index>(i)) = radii[i];
  }
  const Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
  std::array<double, 5> c{};
  for (std::size_t t = 0; t < terms; ++t) c[t] = x(static_cast<Eigen::Index>(t));
  return c;
}

double curve_at(const std::array<double, 5>& c, double theta_deg) {
  const std::array<double, 5> f = basis(theta_deg);
  return std::inner_product(f.begin(), f.end(), c.begin(), 0.0);
}

// The lines within `tolerance` of `expected`: the nearest, and whether there are two.
struct Match {
  std::optional<RayPeak> peak;
  bool ambiguous = false;
};
Match match(const std::vector<RayPeak>& peaks, double expected, double tolerance) {
  Match m;
  for (const RayPeak& p : peaks) {
    if (std::abs(p.radius_px - expected) > tolerance) continue;
    m.ambiguous |= m.peak.has_value();
    if (!m.peak || std::abs(p.radius_px - expected) < std::abs(m.peak->radius_px - expected))
      m.peak = p;
  }
  return m;
}

// One ring followed around the image from its course `course` (per direction): lines matched
// within the tolerance and the curve refitted, kFollowRounds times, leaving out lines far from
// the last curve.
std::array<double, 5> follow(const std::vector<std::vector<RayPeak>>& peaks,
                             const std::vector<double>& thetas, std::vector<double> course,
                             double tolerance) {
  std::array<double, 5> curve{};
  for (int round = 0; round < kFollowRounds; ++round) {
    std::vector<double> t, r;
    for (std::size_t d = 0; d < thetas.size(); ++d) {
      const Match m = match(peaks[d], course[d], tolerance);
      if (!m.peak) continue;
      t.push_back(thetas[d]);
      r.push_back(m.peak->radius_px);
    }
    if (r.empty()) break;
    curve = fit_curve(t, r);
    std::vector<double> kept_t, kept_r;  // the fit again without the lines far from it
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (std::abs(r[i] - curve_at(curve, t[i])) > 0.5 * tolerance) continue;
      kept_t.push_back(t[i]);
      kept_r.push_back(r[i]);
    }
    if (!kept_r.empty()) curve = fit_curve(kept_t, kept_r);
    for (std::size_t d = 0; d < thetas.size(); ++d) course[d] = curve_at(curve, thetas[d]);
  }
  return curve;
}

// The spans of directions, in image-angle order, where every ring is missing.
std::vector<BlockedSpan> blocked_spans(const std::vector<RingDirection>& directions) {
  std::vector<std::size_t> order(directions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return wrap_deg_360(directions[a].theta_deg) < wrap_deg_360(directions[b].theta_deg);
  });
  std::vector<double> angle;  // in that order, in [0, 360)
  for (const std::size_t i : order) angle.push_back(wrap_deg_360(directions[i].theta_deg));
  const auto blocked = [&](std::size_t i) {
    const RingDirection& d = directions[order[i]];
    return std::none_of(d.radius_px.begin(), d.radius_px.end(),
                        [](const std::optional<double>& r) { return r.has_value(); });
  };
  std::vector<BlockedSpan> spans;
  const std::size_t n = order.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!blocked(i) || (i > 0 && blocked(i - 1))) continue;
    std::size_t end = i;
    while (end + 1 < n && blocked(end + 1)) ++end;
    spans.push_back({angle[i], angle[end], end - i + 1});
  }
  // A span across 0 deg: the last one runs on into the first, where the directions go round the
  // circle (the gap across 0 deg no wider than 1.5 times their median spacing).
  std::vector<double> gaps;
  for (std::size_t i = 1; i < n; ++i) gaps.push_back(angle[i] - angle[i - 1]);
  const bool round = n > 1 && 360.0 + angle[0] - angle[n - 1] <= 1.5 * median(gaps);
  if (round && spans.size() > 1 && blocked(0) && blocked(n - 1)) {
    spans.front().from_deg = spans.back().from_deg;
    spans.front().directions += spans.back().directions;
    spans.pop_back();
  }
  return spans;
}

}  // namespace

double RingCurve::radius_at(double theta_deg) const {
  return curve_at(coefficients, theta_deg);
}

void RingSearchOptions::validate() const {
  require(!distances_m.empty() && distances_m.size() <= 64, "distances_m", "expected 1 to 64");
  for (std::size_t k = 0; k < distances_m.size(); ++k) {
    require(std::isfinite(distances_m[k]) && distances_m[k] > 0.0 &&
                (k == 0 || distances_m[k] > distances_m[k - 1]),
            "distances_m", "expected positive distances, increasing");
  }
  require(directions >= 8 && directions <= 3600, "directions", "expected 8 to 3600");
  validate_ray_radii(min_radius_px, max_radius_px);
  peaks().validate();
  require(std::isfinite(tolerance_px) && tolerance_px > 0.0 && tolerance_px <= 50.0, "tolerance_px",
          "expected a number in (0, 50]");
  require(std::isfinite(min_support) && min_support > 0.0 && min_support <= 1.0, "min_support",
          "expected a number in (0, 1]");
  require(std::isfinite(max_decentring_px) && max_decentring_px >= 0.0 && max_decentring_px <= 50.0,
          "max_decentring_px", "expected 0 to 50");
}

RingSearch find_omni_rings(const cv::Mat1b& grey, const Vec2& center,
                           const RingSearchOptions& options,
                           std::span<const double> directions_deg) {
  options.validate();
  const auto [r0, r1] = ray_span(grey, center, options.min_radius_px, options.max_radius_px);
  require(directions_deg.size() <= 3600, "directions", "expected at most 3600");
  require(std::all_of(directions_deg.begin(), directions_deg.end(),
                      [](double theta) { return std::isfinite(theta); }),
          "directions", "expected finite image angles");
  std::vector<double> thetas(directions_deg.begin(), directions_deg.end());
  if (thetas.empty()) {
    for (int i = 0; i < options.directions; ++i) thetas.push_back(360.0 * i / options.directions);
  }
  std::vector<std::vector<RayPeak>> peaks;
  std::vector<Vec2> units;
  for (const double theta : thetas) {
    peaks.push_back(ray_peaks(grey, center, theta, r0, r1, options.peaks()));
    units.push_back(direction_of(theta));
  }
  const int bins = static_cast<int>(std::ceil(r1 - r0)) + 1;
  RingSearch search;
  search.decentring_px = decentring(peaks, units, r0, bins, options);
  const std::vector<Mode> found_modes =
      modes(peaks, units, search.decentring_px, r0, bins, options);
  const std::vector<std::size_t> chain =
      ring_chain(found_modes, options.distances_m, options.tolerance_px);
  const std::size_t rings = options.distances_m.size();
  require(chain.size() == rings, "image",
          "shows " + std::to_string(chain.size()) + " rings in at least " +
              std::to_string(static_cast<int>(std::lround(100.0 * options.min_support))) +
              " % of the directions spaced as lines at the given distances, expected " +
              std::to_string(rings) + "; check the centre, the distances and the contrast");

  search.directions.resize(thetas.size());
  for (std::size_t d = 0; d < thetas.size(); ++d) {
    search.directions[d].theta_deg = thetas[d];
    search.directions[d].radius_px.assign(rings, std::nullopt);
    search.directions[d].miss.assign(rings, RingMiss::kHidden);
  }
  for (std::size_t k = 0; k < rings; ++k) {
    std::vector<double> course(thetas.size());
    for (std::size_t d = 0; d < thetas.size(); ++d)
      course[d] = found_modes[chain[k]].radius_px + search.decentring_px.dot(units[d]);
    const std::array<double, 5> curve = follow(peaks, thetas, course, options.tolerance_px);
    // The lines near the curve, each direction's course the curve moved by its neighbours'
    // departures from it (a ring is not quite the curve: the mirror's own shape).
    std::vector<double> on_curve(thetas.size());
    std::vector<std::optional<RayPeak>> near(thetas.size());
    for (std::size_t d = 0; d < thetas.size(); ++d) {
      on_curve[d] = curve_at(curve, thetas[d]);
      near[d] = match(peaks[d], on_curve[d], 0.5 * options.tolerance_px).peak;
    }
    RingCurve ring;
    std::vector<double> found_t, found_r;
    for (std::size_t d = 0; d < thetas.size(); ++d) {
      std::vector<double> departures, heights;
      for (std::size_t e = 0; e < thetas.size(); ++e) {
        if (near[e] && std::abs(wrap_deg_180(thetas[d] - thetas[e])) <= kFollowWindowDeg) {
          departures.push_back(near[e]->radius_px - on_curve[e]);
          heights.push_back(near[e]->height);
        }
      }
      const double local = on_curve[d] + (departures.size() >= 3 ? median(departures) : 0.0);
      const Match m = match(peaks[d], local, 0.5 * options.tolerance_px);
      RingMiss miss = m.ambiguous ? RingMiss::kAmbiguous
                      : m.peak    ? RingMiss::kNone
                                  : RingMiss::kHidden;
      if (miss == RingMiss::kNone && heights.size() >= 3 &&
          m.peak->height < kMinRelativeHeight * median(heights))
        miss = RingMiss::kHidden;
      search.directions[d].miss[k] = miss;
      search.hidden += miss == RingMiss::kHidden ? 1 : 0;
      search.ambiguous += miss == RingMiss::kAmbiguous ? 1 : 0;
      if (miss != RingMiss::kNone) continue;
      search.directions[d].radius_px[k] = m.peak->radius_px;
      found_t.push_back(thetas[d]);
      found_r.push_back(m.peak->radius_px);
    }
    ring.coefficients = found_r.empty() ? curve : fit_curve(found_t, found_r);
    ring.found_fraction = static_cast<double>(found_r.size()) / static_cast<double>(thetas.size());
    if (!found_r.empty()) {
      ring.median_radius_px = median(found_r);
      std::vector<double> residuals;
      for (std::size_t i = 0; i < found_r.size(); ++i)
        residuals.push_back(std::abs(found_r[i] - ring.radius_at(found_t[i])));
      ring.residual_px = median(residuals);
    } else {
      ring.median_radius_px = ring.radius_at(0.0);
    }
    search.rings.push_back(ring);
  }
  search.blocked = blocked_spans(search.directions);
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
        cv::drawMarker(plot, at(d.theta_deg, search.rings[k].radius_at(d.theta_deg)), colour,
                       cv::MARKER_CROSS, 6, 1);
      }
    }
  }
  mark_ray_plot_center(plot, center);
  return plot;
}

}  // namespace ballsight
