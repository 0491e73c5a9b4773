#include "ballsight/viz/route_plot.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/viz/chart.hpp"

namespace ballsight {
namespace {

const cv::Scalar kBall(45, 230, 225), kBallEdge(20, 60, 60);

/// Field rectangle to show: the fence with a margin, or the points' bounding box.
std::pair<Vec2, Vec2> view_bounds(const PlanningProblem& problem,
                                  const std::vector<RouteLayer>& layers) {
  if (problem.court) {
    const Vec2 margin(1.0, 1.0);
    return {problem.court->area_min_m - margin, problem.court->area_max_m + margin};
  }
  Vec2 lo = problem.robot.position, hi = lo;
  const auto grow = [&](const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const Vec2& b : problem.balls) grow(b);
  for (const RouteLayer& layer : layers) {
    for (const Vec2& w : layer.route.waypoints_m) grow(w);
  }
  const Vec2 margin = 0.05 * (hi - lo) + Vec2(0.5, 0.5);
  return {lo - margin, hi + margin};
}

}  // namespace

cv::Mat draw_route_map(const PlanningProblem& problem, const CourtFloor& floor,
                       const std::vector<RouteLayer>& layers, const std::string& title,
                       double pixels_per_m) {
  auto [lo, hi] = view_bounds(problem, layers);
  // A plain point problem keeps the picture's longer side about 1200 px whatever its units.
  if (!problem.court) pixels_per_m = 1200.0 / std::max((hi - lo).maxCoeff(), 1e-9);
  std::vector<LegendEntry> legend;
  for (const RouteLayer& layer : layers) legend.push_back({layer.label, layer.colour});
  const int top = 36 + 22 * static_cast<int>(legend.size());
  const int width = static_cast<int>(std::lround((hi.x() - lo.x()) * pixels_per_m));
  const int height = top + static_cast<int>(std::lround((hi.y() - lo.y()) * pixels_per_m));
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(235, 235, 235));
  const MapView px{Vec2(lo.x(), hi.y()), pixels_per_m, {0.0, static_cast<double>(top)}};
  if (problem.court) {
    CourtFloor shown = floor;
    // A court planned without a net is drawn without one.
    if (!problem.court->net) shown.net_posts_y_m.reset();
    draw_court_floor(image, px, shown);
    cv::rectangle(image, px(problem.court->area_min_m), px(problem.court->area_max_m),
                  cv::Scalar(60, 60, 60), 2);
    if (const auto& net = problem.court->net) {  // the lane round the net drawn above
      const FieldRect lane = net->lane();
      cv::rectangle(image, px({lane.min_m.x(), lane.max_m.y()}),
                    px({lane.max_m.x(), lane.min_m.y()}), cv::Scalar(120, 120, 120), 1,
                    cv::LINE_AA);
    }
  }
  const int ball_px =
      std::max(3, static_cast<int>(std::lround(problem.ball_radius_m * pixels_per_m)));
  for (std::size_t i = 0; i < problem.balls.size(); ++i) {
    const bool reachable = !problem.court || problem.court->in_area(problem.balls[i]);
    cv::circle(image, px(problem.balls[i]), ball_px, reachable ? kBall : cv::Scalar(160, 160, 160),
               cv::FILLED, cv::LINE_AA);
    cv::circle(image, px(problem.balls[i]), ball_px, kBallEdge, 1, cv::LINE_AA);
  }
  for (const RouteLayer& layer : layers) {
    std::vector<cv::Point> path;
    for (const Vec2& w : layer.route.waypoints_m) path.emplace_back(px(w));
    cv::polylines(image, path, false, layer.colour, 2, cv::LINE_AA);
    if (layer.route.order.size() > 60) continue;  // numbers would cover the picture
    for (std::size_t k = 0; k < layer.route.visits_m.size(); ++k) {
      const cv::Point2d at = px(layer.route.visits_m[k]);
      draw_text(image, std::to_string(k + 1),
                {static_cast<int>(at.x) + 5, static_cast<int>(at.y) - 5}, 0.4, layer.colour);
    }
  }
  if (problem.capacity) {
    cv::drawMarker(image, px(problem.capacity->unload_m), cv::Scalar(0, 0, 200), cv::MARKER_SQUARE,
                   16, 2, cv::LINE_AA);
  }
  const Vec2 forward(std::cos(problem.robot.heading_rad), std::sin(problem.robot.heading_rad));
  const double arrow_m = 40.0 / pixels_per_m;
  cv::arrowedLine(image, px(problem.robot.position), px(problem.robot.position + arrow_m * forward),
                  cv::Scalar(20, 20, 20), 3, cv::LINE_AA, 0, 0.3);
  cv::rectangle(image, {0, 0, image.cols, top}, cv::Scalar::all(255), cv::FILLED);
  draw_text(image, title, {10, 24}, 0.6);
  draw_legend(image, {10, 32}, legend);
  return image;
}

}  // namespace ballsight
