#include "ballsight/viz/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace ballsight {

namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kInk(30, 30, 30);
const cv::Scalar kGrid(225, 225, 225);

double nice_step(double span, int target) {
  const double raw = span / std::max(target, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * magnitude >= raw) return m * magnitude;
  }
  return 10.0 * magnitude;
}

std::string tick_label(double value, double step) {
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

cv::Size text_size(const std::string& text, double scale, int thickness = 1) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, thickness, &baseline);
}

}  // namespace

cv::Point2d ChartAxes::to_image(double x, double y) const {
  return {area.x + (x - x_min) / (x_max - x_min) * area.width,
          area.y + area.height - (y - y_min) / (y_max - y_min) * area.height};
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo)) return ticks;
  const double step = nice_step(hi - lo, target);
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

double nice_ceil(double hi) {
  if (!(hi > 0.0)) return 1.0;
  const double step = nice_step(hi, 5);
  return std::ceil(hi / step - 1e-9) * step;
}

void draw_text(cv::Mat& bgr, const std::string& text, cv::Point origin, double scale,
               const cv::Scalar& colour, int thickness) {
  cv::putText(bgr, text, origin, kFont, scale, colour, thickness, cv::LINE_AA);
}

void draw_axes(cv::Mat& bgr, const ChartAxes& axes, const std::string& x_label,
               const std::string& y_label, const std::string& title) {
  const cv::Rect& a = axes.area;
  const std::vector<double> x_ticks = nice_ticks(axes.x_min, axes.x_max, 8);
  const std::vector<double> y_ticks = nice_ticks(axes.y_min, axes.y_max, 8);
  const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  int widest_y_label = 0;
  for (const double x : x_ticks) {
    const int px = static_cast<int>(std::lround(axes.to_image(x, axes.y_min).x));
    cv::line(bgr, {px, a.y}, {px, a.y + a.height}, kGrid, 1);
    cv::line(bgr, {px, a.y + a.height}, {px, a.y + a.height + 5}, kInk, 1);
    const std::string label = tick_label(x, x_step);
    draw_text(bgr, label, {px - text_size(label, 0.45).width / 2, a.y + a.height + 22}, 0.45);
  }
  for (const double y : y_ticks) {
    const int py = static_cast<int>(std::lround(axes.to_image(axes.x_min, y).y));
    cv::line(bgr, {a.x, py}, {a.x + a.width, py}, kGrid, 1);
    cv::line(bgr, {a.x - 5, py}, {a.x, py}, kInk, 1);
    const std::string label = tick_label(y, y_step);
    const int w = text_size(label, 0.45).width;
    widest_y_label = std::max(widest_y_label, w);
    draw_text(bgr, label, {a.x - 9 - w, py + 5}, 0.45);
  }
  cv::rectangle(bgr, a, kInk, 1);
  const cv::Size xs = text_size(x_label, 0.55);
  draw_text(bgr, x_label, {a.x + (a.width - xs.width) / 2, a.y + a.height + 48}, 0.55);
  // The y label: drawn horizontally on a strip, then turned a quarter counter-clockwise.
  const cv::Size ys = text_size(y_label, 0.55);
  cv::Mat strip(ys.height + 10, ys.width + 4, bgr.type(), cv::Scalar::all(255));
  draw_text(strip, y_label, {2, ys.height + 3}, 0.55);
  cv::Mat turned;
  cv::rotate(strip, turned, cv::ROTATE_90_COUNTERCLOCKWISE);
  const int lx = a.x - 16 - widest_y_label - turned.cols;
  const int ly = a.y + (a.height - turned.rows) / 2;
  if (lx >= 0 && ly >= 0 && ly + turned.rows <= bgr.rows) {
    turned.copyTo(bgr(cv::Rect(lx, ly, turned.cols, turned.rows)));
  }
  draw_text(bgr, title, {a.x, a.y - 12}, 0.6, kInk, 1);
}

void draw_series(cv::Mat& bgr, const ChartAxes& axes, std::span<const double> xs,
                 std::span<const double> ys, const cv::Scalar& colour, int thickness) {
  cv::Mat roi = bgr(axes.area);
  const cv::Point2d offset(axes.area.x, axes.area.y);
  std::vector<cv::Point> run;
  const auto flush = [&] {
    if (run.size() > 1) cv::polylines(roi, run, false, colour, thickness, cv::LINE_AA);
    run.clear();
  };
  for (std::size_t i = 0; i < std::min(xs.size(), ys.size()); ++i) {
    if (!std::isfinite(xs[i]) || !std::isfinite(ys[i])) {
      flush();
      continue;
    }
    const double y = std::clamp(ys[i], axes.y_min - 0.05 * (axes.y_max - axes.y_min),
                                axes.y_max + 0.05 * (axes.y_max - axes.y_min));
    const cv::Point2d p = axes.to_image(xs[i], y) - offset;
    run.emplace_back(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
  }
  flush();
}

void draw_vertical_marker(cv::Mat& bgr, const ChartAxes& axes, double x, const cv::Scalar& colour,
                          const std::string& label) {
  const int px = static_cast<int>(std::lround(axes.to_image(x, axes.y_min).x));
  const cv::Rect& a = axes.area;
  for (int y = a.y; y < a.y + a.height; y += 12) {
    cv::line(bgr, {px, y}, {px, std::min(y + 6, a.y + a.height)}, colour, 2);
  }
  const int w = text_size(label, 0.45).width;
  const int tx = px + 6 + w < a.x + a.width ? px + 6 : px - 6 - w;
  draw_text(bgr, label, {tx, a.y + 18}, 0.45, colour);
}

void draw_legend(cv::Mat& bgr, cv::Point top_left, std::span<const LegendEntry> entries) {
  int width = 0;
  for (const LegendEntry& e : entries) width = std::max(width, text_size(e.label, 0.45).width);
  const int row = 20;
  const cv::Rect box(top_left.x, top_left.y, width + 50,
                     row * static_cast<int>(entries.size()) + 8);
  cv::rectangle(bgr, box, cv::Scalar::all(255), cv::FILLED);
  cv::rectangle(bgr, box, kInk, 1);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = top_left.y + 4 + row * static_cast<int>(i) + row / 2;
    cv::line(bgr, {top_left.x + 8, y}, {top_left.x + 34, y}, entries[i].colour, 2, cv::LINE_AA);
    draw_text(bgr, entries[i].label, {top_left.x + 42, y + 5}, 0.45);
  }
}

cv::Mat colorize(const cv::Mat1f& values, int colormap, double lo, double hi,
                 const cv::Scalar& invalid_colour) {
  cv::Mat1b levels(values.size());
  cv::Mat1b invalid(values.size());
  const double scale = 255.0 / std::max(hi - lo, 1e-12);
  for (int y = 0; y < values.rows; ++y) {
    for (int x = 0; x < values.cols; ++x) {
      const float v = values(y, x);
      invalid(y, x) = std::isfinite(v) ? 0 : 255;
      levels(y, x) = std::isfinite(v) ? cv::saturate_cast<uchar>((v - lo) * scale) : uchar{0};
    }
  }
  cv::Mat bgr;
  cv::applyColorMap(levels, bgr, colormap);
  bgr.setTo(invalid_colour, invalid);
  return bgr;
}

void draw_color_bar(cv::Mat& bgr, const cv::Rect& area, int colormap, double lo, double hi,
                    const std::string& label) {
  cv::Mat1f ramp(area.height, area.width);
  for (int y = 0; y < area.height; ++y) {
    ramp.row(y).setTo(hi - (hi - lo) * y / std::max(area.height - 1, 1));
  }
  colorize(ramp, colormap, lo, hi, cv::Scalar::all(0)).copyTo(bgr(area));
  cv::rectangle(bgr, area, kInk, 1);
  const std::vector<double> ticks = nice_ticks(lo, hi, 6);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  for (const double t : ticks) {
    const int y = area.y + static_cast<int>(std::lround((hi - t) / (hi - lo) * (area.height - 1)));
    cv::line(bgr, {area.x + area.width, y}, {area.x + area.width + 5, y}, kInk, 1);
    draw_text(bgr, tick_label(t, step), {area.x + area.width + 8, y + 5}, 0.45);
  }
  draw_text(bgr, label, {area.x, area.y + area.height + 22}, 0.5);
}

}  // namespace ballsight
