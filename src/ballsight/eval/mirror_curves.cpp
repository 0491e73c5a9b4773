#include "ballsight/eval/mirror_curves.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <span>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/viz/chart.hpp"

namespace ballsight {

namespace {

constexpr MirrorKind kKinds[] = {MirrorKind::kUnified, MirrorKind::kSphere, MirrorKind::kCone,
                                 MirrorKind::kTable};
constexpr double kSameDistanceM = 0.001;

// Line colours: the simulated mirrors in cool tones, the real sets in warm ones.
const cv::Scalar kSimulatedColours[] = {{160, 60, 0}, {200, 150, 0}, {120, 120, 120}, {80, 160, 0}};
const cv::Scalar kRealColours[] = {{30, 30, 200}, {0, 130, 230}, {160, 40, 160}, {60, 80, 140},
                                   {0, 190, 190}, {90, 0, 110},  {40, 40, 40}};

// The curve's radii over its radius at 1 m (nullopt when it does not reach 1 m).
std::optional<std::vector<double>> shape(const MirrorCurve& curve) {
  const std::optional<double> at_1m = curve.radius_at(1.0);
  if (!at_1m) return std::nullopt;
  std::vector<double> out;
  for (const double r : curve.radius_px) out.push_back(r / *at_1m);
  return out;
}

}  // namespace

std::optional<double> MirrorCurve::radius_at(double d) const {
  if (distance_m.empty() || d < distance_m.front() || d > distance_m.back()) return std::nullopt;
  const auto upper = std::upper_bound(distance_m.begin(), distance_m.end(), d);
  if (upper == distance_m.end()) return radius_px.back();
  const auto i = static_cast<std::size_t>(upper - distance_m.begin());
  const double t = (d - distance_m[i - 1]) / (distance_m[i] - distance_m[i - 1]);
  return radius_px[i - 1] + t * (radius_px[i] - radius_px[i - 1]);
}

std::optional<double> MirrorCurve::radius_sampled_at(double d) const {
  for (std::size_t i = 0; i < distance_m.size(); ++i) {
    if (std::abs(distance_m[i] - d) < kSameDistanceM) return radius_px[i];
  }
  return std::nullopt;
}

std::vector<MirrorCurve> simulated_mirror_curves(double min_m, double max_m, double step_m) {
  require(min_m >= 0.0 && max_m >= min_m && step_m > 0.0, "mirror curve distances",
          "expected 0 <= min <= max and a positive step");
  std::vector<MirrorCurve> curves;
  for (const MirrorKind kind : kKinds) {
    const OmniRig rig(with_mirror(OmniRigParams{}, kind));
    MirrorCurve& curve = curves.emplace_back();
    curve.name = "sim " + std::string(mirror_kind_name(kind));
    curve.simulated = true;
    const int steps = static_cast<int>(std::floor((max_m - min_m) / step_m + 1e-9));
    for (int i = 0; i <= steps; ++i) {
      const double d = min_m + i * step_m;
      if (const auto pixel = rig.pixel_from_point({d, 0.0, 0.0})) {
        curve.distance_m.push_back(d);
        curve.radius_px.push_back((*pixel - rig.principal_point()).norm());
      }
    }
  }
  return curves;
}

std::vector<MirrorCurve> real_mirror_curves(const std::vector<RealOmniSet>& sets) {
  std::vector<MirrorCurve> curves;
  for (const RealOmniSet& set : sets) {
    std::map<double, std::pair<double, int>> by_distance;  // cm -> (sum of radii, count)
    for (const PolarSample& s : set.samples) {
      auto& [sum, count] = by_distance[s.distance_cm];
      sum += s.radius_px;
      ++count;
    }
    MirrorCurve& curve = curves.emplace_back();
    curve.name = set.name;
    for (const auto& [distance_cm, sum_count] : by_distance) {
      curve.distance_m.push_back(distance_cm / 100.0);
      curve.radius_px.push_back(sum_count.first / sum_count.second);
    }
  }
  return curves;
}

cv::Mat plot_mirror_curves(const std::vector<MirrorCurve>& curves) {
  constexpr int kWidth = 560, kHeight = 420, kMargin = 80;
  double max_m = 1.0, max_px = 1.0, max_shape = 1.0;
  for (const MirrorCurve& c : curves) {
    if (c.distance_m.empty()) continue;
    max_m = std::max(max_m, c.distance_m.back());
    max_px = std::max(max_px, *std::max_element(c.radius_px.begin(), c.radius_px.end()));
    if (const auto s = shape(c))
      max_shape = std::max(max_shape, *std::max_element(s->begin(), s->end()));
  }
  cv::Mat figure(kHeight + 2 * kMargin + 40 + 22 * static_cast<int>(curves.size() + 1) / 2,
                 2 * (kWidth + kMargin) + kMargin, CV_8UC3, cv::Scalar(255, 255, 255));
  const ChartAxes pixels{cv::Rect(kMargin, kMargin, kWidth, kHeight), 0.0, nice_ceil(max_m), 0.0,
                         nice_ceil(max_px)};
  const ChartAxes shapes{cv::Rect(2 * kMargin + kWidth, kMargin, kWidth, kHeight), 0.0,
                         nice_ceil(max_m), 0.0, nice_ceil(max_shape)};
  draw_axes(figure, pixels, "floor distance (m)", "image radius (px)",
            "image radius of a floor point");
  draw_axes(figure, shapes, "floor distance (m)", "radius / radius at 1 m",
            "the same, each over its radius at 1 m");
  std::vector<LegendEntry> legend;
  std::size_t simulated = 0, real = 0;
  for (const MirrorCurve& c : curves) {
    const cv::Scalar colour = c.simulated
                                  ? kSimulatedColours[simulated++ % std::size(kSimulatedColours)]
                                  : kRealColours[real++ % std::size(kRealColours)];
    legend.push_back({c.name + (c.simulated ? " (line)" : " (points)"), colour});
    const std::optional<std::vector<double>> s = shape(c);
    for (const auto& [axes, ys] :
         {std::pair{&pixels, std::optional(c.radius_px)}, std::pair{&shapes, s}}) {
      if (!ys) continue;
      draw_series(figure, *axes, c.distance_m, *ys, colour, c.simulated ? 2 : 1);
      if (c.simulated) continue;
      for (std::size_t i = 0; i < ys->size(); ++i) {
        cv::circle(figure, axes->to_image(c.distance_m[i], (*ys)[i]), 4, colour, cv::FILLED,
                   cv::LINE_AA);
      }
    }
  }
  const std::size_t half = (legend.size() + 1) / 2;
  const std::span<const LegendEntry> entries(legend);
  if (half > 0) draw_legend(figure, {kMargin + 10, kHeight + kMargin + 60}, entries.first(half));
  if (legend.size() > half) {
    draw_legend(figure, {2 * kMargin + kWidth + 10, kHeight + kMargin + 60}, entries.subspan(half));
  }
  return figure;
}

std::string mirror_curves_table(const std::vector<MirrorCurve>& curves,
                                const std::vector<double>& columns_m) {
  std::size_t width = 5;
  for (const MirrorCurve& c : curves) width = std::max(width, c.name.size());
  const auto pad = [](std::string text, std::size_t n) {
    return text.size() < n ? std::string(n - text.size(), ' ') + text : text;
  };
  std::string out = std::string("curve") + std::string(width - 5, ' ');
  for (const double d : columns_m) out += pad(fixed(d, 2) + " m", 9);
  out += "   (radius, px; ~ linear between a real set's distances)\n";
  for (const MirrorCurve& c : curves) {
    out += c.name + std::string(width - c.name.size(), ' ');
    for (const double d : columns_m) {
      // A real set between its distances: linear, marked "~".
      const std::optional<double> sampled = c.simulated ? c.radius_at(d) : c.radius_sampled_at(d);
      const std::optional<double> between = c.radius_at(d);
      std::string cell;
      if (sampled) {
        cell = fixed(*sampled, 1);
      } else if (between) {
        cell = "~";
        cell += fixed(*between, 1);
      }
      out += pad(cell, 9);
    }
    out += "\n";
  }
  return out;
}

nlohmann::json mirror_curves_json(const std::vector<MirrorCurve>& curves) {
  nlohmann::json list = nlohmann::json::array();
  for (const MirrorCurve& c : curves) {
    list.push_back({{"name", c.name},
                    {"simulated", c.simulated},
                    {"distance_m", c.distance_m},
                    {"radius_px", c.radius_px}});
  }
  return {{"curves", list}};
}

}  // namespace ballsight
