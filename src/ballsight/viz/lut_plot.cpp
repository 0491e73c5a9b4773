#include "ballsight/viz/lut_plot.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/text_format.hpp"
#include "ballsight/viz/chart.hpp"

namespace ballsight {

namespace {

constexpr int kWidth = 1500;
constexpr int kHeight = 730;
constexpr int kDistanceColormap = cv::COLORMAP_TURBO;
const cv::Scalar kMarker(40, 40, 220);
const cv::Scalar kInvalid(235, 235, 235);

// One colour per plotted direction (BGR, colour-blind friendly Okabe-Ito palette + black).
const std::array<cv::Scalar, kLutFigureDirectionsDeg.size()> kDirectionColours{{
    {0, 0, 0},
    {0, 159, 230},
    {233, 180, 86},
    {115, 158, 0},
    {66, 228, 240},
    {178, 114, 0},
    {0, 94, 213},
    {167, 121, 204},
}};

void draw_profiles(cv::Mat& figure, const LutFigureInput& lut, double max_cm) {
  const ChartAxes axes{cv::Rect(110, 130, 740, 520), 0.0, lut.radius_end_px, 0.0, max_cm};
  draw_axes(figure, axes, "pixel radius from the image centre (px)", "ground distance (cm)",
            "Distance along rays (written range only)");
  std::vector<LegendEntry> legend;
  for (std::size_t k = 0; k < kLutFigureDirectionsDeg.size(); ++k) {
    const std::optional<LutProfile>& profile = lut.profiles[k];
    if (!profile) continue;
    const cv::Scalar& colour = kDirectionColours[k];
    draw_series(figure, axes, lut.radius_px, profile->distance_cm, colour, 2);
    if (profile->drop_px) {
      const cv::Point2d p = axes.to_image(*profile->drop_px, profile->distance_at_drop_cm);
      cv::circle(figure, cv::Point(static_cast<int>(p.x), static_cast<int>(p.y)), 5, colour, 2,
                 cv::LINE_AA);
    }
    legend.push_back(
        {"theta " + std::to_string(kLutFigureDirectionsDeg[k]) + " deg" +
             (profile->drop_px ? ", drops at " + fixed(*profile->drop_px, 1) + " px" : ""),
         colour});
  }
  if (lut.monotonic_until_px) {
    draw_vertical_marker(figure, axes, *lut.monotonic_until_px, kMarker, lut.monotonic_label);
  }
  draw_legend(figure, {axes.area.x + 12, axes.area.y + 30}, legend);
}

void draw_heat_map(cv::Mat& figure, const LutFigureInput& lut, double max_cm) {
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
  if (lut.monotonic_until_px) {
    cv::circle(figure, to_point(center), static_cast<int>(*lut.monotonic_until_px * scale),
               cv::Scalar::all(255), 2, cv::LINE_AA);
  }
  for (std::size_t k = 0; k < kLutFigureDirectionsDeg.size(); ++k) {
    // The plotted rays, as ticks at the image border.
    const double t = kLutFigureDirectionsDeg[k] * CV_PI / 180.0;
    const cv::Point2d dir(std::cos(t), -std::sin(t));
    const double reach = 0.5 * std::min(size.width, size.height) - 2.0;
    cv::line(figure, to_point(center + dir * (reach - 18.0)), to_point(center + dir * reach),
             kDirectionColours[k], 3, cv::LINE_AA);
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

cv::Mat plot_lut_figure(const LutFigureInput& lut) {
  cv::Mat figure(kHeight, kWidth, CV_8UC3, cv::Scalar::all(255));
  const double max_cm = nice_ceil(lut.largest_distance_cm);
  draw_text(figure, lut.title, {20, 32}, 0.65, {0, 0, 0}, 2);
  draw_text(figure, lut.summary, {20, 62}, 0.55);
  draw_profiles(figure, lut, max_cm);
  draw_heat_map(figure, lut, max_cm);
  return figure;
}

}  // namespace ballsight
