#pragma once
// Chart primitives for the plots, drawn with OpenCV: axes with grid and tick labels, line
// series, a legend, and colour-mapped images with a scale bar.

#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <vector>

namespace ballsight {

/// A plot area in an image and the data range it shows.
struct ChartAxes {
  cv::Rect area;
  double x_min = 0.0, x_max = 1.0;
  double y_min = 0.0, y_max = 1.0;

  cv::Point2d to_image(double x, double y) const;
};

/// Round tick values (1, 2 or 5 x 10^k apart) inside [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

/// `hi` rounded up to a value a tick would have.
double nice_ceil(double hi);

/// Frame, grid, tick labels, axis labels (the y label rotated) and a title above the area.
void draw_axes(cv::Mat& bgr, const ChartAxes& axes, const std::string& x_label,
               const std::string& y_label, const std::string& title);

/// A polyline through (xs[i], ys[i]), clipped to the area; a NaN breaks the line.
void draw_series(cv::Mat& bgr, const ChartAxes& axes, std::span<const double> xs,
                 std::span<const double> ys, const cv::Scalar& colour, int thickness = 2);

/// A dashed vertical line at x with a label at its top.
void draw_vertical_marker(cv::Mat& bgr, const ChartAxes& axes, double x, const cv::Scalar& colour,
                          const std::string& label);

struct LegendEntry {
  std::string label;
  cv::Scalar colour;
};

/// A boxed legend with its top-left corner at `top_left`.
void draw_legend(cv::Mat& bgr, cv::Point top_left, std::span<const LegendEntry> entries);

/// Values in [lo, hi] coloured with cv::applyColorMap's `colormap`; NaN -> `invalid_colour`.
cv::Mat colorize(const cv::Mat1f& values, int colormap, double lo, double hi,
                 const cv::Scalar& invalid_colour);

/// A vertical colour bar for `colormap` over [lo, hi] (hi at the top) with tick labels and a
/// label below it.
void draw_color_bar(cv::Mat& bgr, const cv::Rect& area, int colormap, double lo, double hi,
                    const std::string& label);

/// Text with the chart's font; `scale` 0.5 is the default label size.
void draw_text(cv::Mat& bgr, const std::string& text, cv::Point origin, double scale = 0.5,
               const cv::Scalar& colour = {30, 30, 30}, int thickness = 1);

}  // namespace ballsight
