#include "ballsight/viz/loop_plot.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/text_format.hpp"
#include "ballsight/viz/chart.hpp"

namespace ballsight {
namespace {

constexpr double kPixelsPerM = 32.0;
constexpr int kTimeColormap = cv::COLORMAP_VIRIDIS;

cv::Scalar colormap_colour(double share) {
  cv::Mat1b v(1, 1, static_cast<uchar>(std::clamp(share, 0.0, 1.0) * 255.0));
  cv::Mat c;
  cv::applyColorMap(v, c, kTimeColormap);
  const cv::Vec3b bgr = c.at<cv::Vec3b>(0, 0);
  return {static_cast<double>(bgr[0]), static_cast<double>(bgr[1]), static_cast<double>(bgr[2])};
}

}  // namespace

cv::Mat draw_loop_map(const CourtFloor& floor, const LoopMapInput& run, const std::string& title,
                      int route_snapshots) {
  const Vec2 lo(-19.0, -10.0), hi(19.0, 10.0);  // the 36 x 18 m fence and a metre round it
  const cv::Scalar route_colours[] = {
      {200, 120, 40}, {40, 140, 230}, {160, 60, 200}, {60, 170, 60}};
  constexpr int kColours = 4;
  route_snapshots = std::clamp(route_snapshots, 0, kColours);
  const int top = 36 + 22 * (route_snapshots + 1);
  const int bar = 90;
  const int width = static_cast<int>(std::lround((hi.x() - lo.x()) * kPixelsPerM)) + bar;
  const int height = top + static_cast<int>(std::lround((hi.y() - lo.y()) * kPixelsPerM));
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(235, 235, 235));
  const MapView px{Vec2(lo.x(), hi.y()), kPixelsPerM, {0.0, static_cast<double>(top)}};
  draw_court_floor(image, px, floor);
  cv::rectangle(image, px({-18, -9}), px({18, 9}), cv::Scalar(60, 60, 60), 2);

  // The true path, and over it the published route at evenly spaced moments of the run.
  std::vector<cv::Point> driven{px(run.robot_start.position)};
  for (const Vec2& p : run.path_m) driven.emplace_back(px(p));
  cv::polylines(image, driven, false, cv::Scalar(20, 20, 20), 2, cv::LINE_AA);

  std::vector<LegendEntry> legend{{"true path", cv::Scalar(20, 20, 20)}};
  for (int k = 0; k < route_snapshots && !run.routes.empty(); ++k) {
    const LoopMapInput::PublishedRoute& route =
        run.routes[run.routes.size() * static_cast<std::size_t>(k) /
                   static_cast<std::size_t>(route_snapshots)];
    std::vector<cv::Point> path;
    for (const Vec2& w : route.waypoints_m) path.emplace_back(px(w));
    cv::polylines(image, path, false, route_colours[k], 2, cv::LINE_AA);
    legend.push_back({"route published at " + fixed(route.time_s, 1) + " s", route_colours[k]});
  }
  // Balls by the time they were collected.
  const double end_s = std::max(1.0, run.duration_s);
  const int r = 5;
  for (const LoopMapInput::Ball& b : run.balls) {
    const cv::Point2d at = px(b.position_m);
    if (!b.collected_s) {
      cv::circle(image, at, r, cv::Scalar(160, 160, 160), cv::FILLED, cv::LINE_AA);
      cv::drawMarker(image, at, cv::Scalar(0, 0, 220), cv::MARKER_TILTED_CROSS, 12, 2);
    } else {
      cv::circle(image, at, r, colormap_colour(*b.collected_s / end_s), cv::FILLED, cv::LINE_AA);
      cv::circle(image, at, r, cv::Scalar(20, 20, 20), 1, cv::LINE_AA);
    }
  }
  const Vec2 forward(std::cos(run.robot_start.heading_rad), std::sin(run.robot_start.heading_rad));
  cv::arrowedLine(image, px(run.robot_start.position), px(run.robot_start.position + 1.2 * forward),
                  cv::Scalar(20, 20, 20), 3, cv::LINE_AA, 0, 0.3);
  draw_color_bar(image, {width - bar + 20, top + 20, 20, height - top - 80}, kTimeColormap, 0.0,
                 end_s, "collected (s)");
  cv::rectangle(image, {0, 0, image.cols, top}, cv::Scalar::all(255), cv::FILLED);
  draw_text(image, title, {10, 24}, 0.6);
  draw_legend(image, {10, 32}, legend);
  return image;
}

cv::Mat draw_latency_chart(const std::vector<std::uint64_t>& seqs,
                           const std::vector<double>& latency_ms, const std::string& title) {
  cv::Mat image(360, 900, CV_8UC3, cv::Scalar::all(255));
  std::vector<double> xs(seqs.begin(), seqs.end());
  const double y_max = nice_ceil(std::max(
      10.0, latency_ms.empty() ? 0.0 : *std::max_element(latency_ms.begin(), latency_ms.end())));
  const ChartAxes axes{
      {70, 40, 800, 270}, 0.0, xs.empty() ? 1.0 : std::max(1.0, xs.back()), 0.0, y_max};
  draw_axes(image, axes, "update (sequence number)", "ms", title);
  draw_series(image, axes, xs, latency_ms, cv::Scalar(180, 90, 30), 1);
  return image;
}

}  // namespace ballsight
