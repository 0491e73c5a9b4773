#include "ballsight/eval/lut_plot.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/eval/chart.hpp"

namespace ballsight {

namespace {

constexpr int kWidth = 1500;
constexpr int kHeight = 730;
constexpr int kDistanceColormap = cv::COLORMAP_TURBO;
const cv::Scalar kMarker(40, 40, 220);
const cv::Scalar kInvalid(235, 235, 235);

// Eight directions, one colour each (BGR, colour-blind friendly Okabe-Ito palette + black).
struct Direction {
  int theta_deg;
  cv::Scalar colour;
};
const Direction kDirections[] = {
    {0, {0, 0, 0}},        {45, {0, 159, 230}},  {90, {233, 180, 86}}, {135, {115, 158, 0}},
    {180, {66, 228, 240}}, {225, {178, 114, 0}}, {270, {0, 94, 213}},  {315, {167, 121, 204}},
};

// The largest plausible written value, to scale the distance axis and the heat map.
double largest_distance_cm(const InspectedLut& lut, const LutInspection& inspection) {
  double largest = 0.0;
  for (int theta = 0; theta < RadialTable::kDirections; ++theta) {
    const RayFindings& f = inspection.rays[static_cast<std::size_t>(theta)];
    if (!f.first_written_px) continue;
    const std::span<const float> ray = lut.rays.ray(theta);
    const auto first = static_cast<std::size_t>(lut.rays.bin_at(*f.first_written_px));
    const auto last = static_cast<std::size_t>(lut.rays.bin_at(*f.last_written_px));
    for (std::size_t i = first; i <= last; ++i) {
      if (std::isfinite(ray[i])) largest = std::max<double>(largest, ray[i]);
    }
  }
  return nice_ceil(largest);
}

std::string summary(const LutInspection& in) {
  std::string text =
      "first written " +
      (in.first_written_min_px ? fixed(*in.first_written_min_px, 1) + " px" : std::string("never"));
  if (in.monotonic_until_px) {
    text += "   monotonic until " + fixed(*in.monotonic_until_px, 1) + " px (" +
            std::to_string(in.non_monotonic_directions) + " of " + std::to_string(in.rays.size()) +
            " directions drop)";
  }
  for (const RadiusSpread& s : in.spread) {
    if (s.radius_px == 200.0) text += "   spread at 200 px " + fixed(s.spread_cm(), 0) + " cm";
  }
  return text + "   holes " + std::to_string(in.holes);
}

void draw_profiles(cv::Mat& figure, const InspectedLut& lut, const LutInspection& inspection,
                   double max_cm) {
  const RadialTable& rays = lut.rays;
  const ChartAxes axes{cv::Rect(110, 130, 740, 520), 0.0, rays.radius_px(rays.bins), 0.0, max_cm};
  draw_axes(figure, axes, "pixel radius from the image centre (px)", "ground distance (cm)",
            "Distance along rays (written range only)");
  std::vector<double> radius(static_cast<std::size_t>(rays.bins));
  for (int bin = 0; bin < rays.bins; ++bin)
    radius[static_cast<std::size_t>(bin)] = rays.radius_px(bin);
  std::vector<LegendEntry> legend;
  for (const Direction& d : kDirections) {
    const RayFindings& f = inspection.rays[static_cast<std::size_t>(d.theta_deg)];
    if (!f.first_written_px) continue;
    std::vector<double> distance(radius.size(), std::nan(""));
    const std::span<const float> ray = rays.ray(d.theta_deg);
    for (std::size_t i = 0; i < radius.size(); ++i) {
      if (radius[i] >= *f.first_written_px && radius[i] <= *f.last_written_px) distance[i] = ray[i];
    }
    draw_series(figure, axes, radius, distance, d.colour, 2);
    if (f.drop_px) {
      const auto bin = static_cast<std::size_t>(rays.bin_at(*f.drop_px));
      const cv::Point2d p = axes.to_image(*f.drop_px, ray[bin]);
      cv::circle(figure, cv::Point(static_cast<int>(p.x), static_cast<int>(p.y)), 5, d.colour, 2,
                 cv::LINE_AA);
    }
    legend.push_back({"theta " + std::to_string(d.theta_deg) + " deg" +
                          (f.drop_px ? ", drops at " + fixed(*f.drop_px, 1) + " px" : ""),
                      d.colour});
  }
  if (inspection.monotonic_until_px) {
    const std::string where = fixed(*inspection.monotonic_until_px, 1) + " px";
    draw_vertical_marker(figure, axes, *inspection.monotonic_until_px, kMarker,
                         inspection.non_monotonic_directions == 0
                             ? "monotonic over the written range (to " + where + ")"
                             : "monotonic until " + where + " (theta " +
                                   std::to_string(inspection.monotonic_until_theta_deg) + ")");
  }
  draw_legend(figure, {axes.area.x + 12, axes.area.y + 30}, legend);
}

void draw_heat_map(cv::Mat& figure, const InspectedLut& lut, const LutInspection& inspection,
                   double max_cm) {
  const cv::Mat1f& image = lut.distance_image_cm;
  const cv::Rect box(930, 130, 440, 520);
  const double scale = std::min(box.width / static_cast<double>(image.cols),
                                box.height / static_cast<double>(image.rows));
  const cv::Size size(static_cast<int>(image.cols * scale), static_cast<int>(image.rows * scale));
  cv::Mat coloured = colorize(image, kDistanceColormap, 0.0, max_cm, kInvalid);
  cv::Mat resized;
  cv::resize(coloured, resized, size, 0.0, 0.0, cv::INTER_NEAREST);
  const cv::Rect area(box.x, box.y, size.width, size.height);
  resized.copyTo(figure(area));
  cv::rectangle(figure, area, cv::Scalar::all(30), 1);
  const cv::Point2d center(area.x + (lut.image_center_px.x() + 0.5) * scale,
                           area.y + (lut.image_center_px.y() + 0.5) * scale);
  const auto to_point = [](const cv::Point2d& p) {
    return cv::Point(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
  };
  if (inspection.monotonic_until_px) {
    cv::circle(figure, to_point(center), static_cast<int>(*inspection.monotonic_until_px * scale),
               cv::Scalar::all(255), 2, cv::LINE_AA);
  }
  for (const Direction& d : kDirections) {  // the plotted rays, as ticks at the image border
    const double t = d.theta_deg * CV_PI / 180.0;
    const cv::Point2d dir(std::cos(t), -std::sin(t));
    const double reach = 0.5 * std::min(size.width, size.height) - 2.0;
    cv::line(figure, to_point(center + dir * (reach - 18.0)), to_point(center + dir * reach),
             d.colour, 3, cv::LINE_AA);
  }
  draw_text(figure,
            "Ground distance over the image (" + std::to_string(image.cols) + "x" +
                std::to_string(image.rows) + " px)",
            {box.x, box.y - 12}, 0.6);
  draw_text(figure, "white circle: monotonic limit; grey: no value",
            {box.x, area.y + area.height + 22}, 0.45);
  draw_color_bar(figure, cv::Rect(box.x + box.width + 25, box.y, 22, area.height),
                 kDistanceColormap, 0.0, max_cm, "cm");
}

}  // namespace

cv::Mat plot_lut_inspection(const InspectedLut& lut, const LutInspection& inspection) {
  cv::Mat figure(kHeight, kWidth, CV_8UC3, cv::Scalar::all(255));
  const double max_cm = largest_distance_cm(lut, inspection);
  draw_text(figure, lut.source + "  (" + inspection.format + ")", {20, 32}, 0.65, {0, 0, 0}, 2);
  draw_text(figure, summary(inspection), {20, 62}, 0.55);
  draw_profiles(figure, lut, inspection, max_cm);
  draw_heat_map(figure, lut, inspection, max_cm);
  return figure;
}

}  // namespace ballsight
