#include <algorithm>
#include <array>
#include <opencv2/imgproc.hpp>

#include "ballsight/eval/chart.hpp"
#include "ballsight/eval/omni_experiment.hpp"

namespace ballsight {

namespace {
const std::map<std::string, cv::Scalar> kColours = {{"poly", {40, 40, 220}},
                                                    {"paper-mlp", {0, 150, 240}},
                                                    {"ballsight", {200, 110, 0}},
                                                    {"oracle", {60, 60, 60}}};
}  // namespace

cv::Mat plot_omni_experiment(const OmniExperimentResult& result) {
  const std::map<std::string, MethodResult>& methods = result.methods;
  std::vector<int> distances;
  for (const auto& [distance, r] : methods.begin()->second.by_distance)
    distances.push_back(distance);
  constexpr int kPanel = 420, kMargin = 70;
  cv::Mat figure(kPanel + 2 * kMargin + 150,
                 static_cast<int>(distances.size()) * (kPanel + kMargin) + kMargin, CV_8UC3,
                 cv::Scalar(255, 255, 255));
  const Vec2 truth = result.options.ball_cm;
  for (size_t i = 0; i < distances.size(); ++i) {
    // A square window around the true ball wide enough for every estimate of this distance.
    double extent = 5.0;
    for (const auto& [name, method] : methods)
      for (const auto& e : method.by_distance.at(distances[i]).estimates_cm)
        if (e) extent = std::max(extent, (*e - truth).cwiseAbs().maxCoeff() * 1.1);
    extent = nice_ceil(extent);
    ChartAxes axes{
        cv::Rect(kMargin + static_cast<int>(i) * (kPanel + kMargin), kMargin, kPanel, kPanel),
        truth.x() - extent, truth.x() + extent, truth.y() - extent, truth.y() + extent};
    draw_axes(figure, axes, "field x (cm)", "field y (cm)",
              "robot " + std::to_string(distances[i]) + " cm from the ball");
    cv::drawMarker(figure, axes.to_image(truth.x(), truth.y()), {0, 0, 0}, cv::MARKER_CROSS, 18, 2);
    for (const auto& [name, method] : methods) {
      for (const auto& e : method.by_distance.at(distances[i]).estimates_cm) {
        if (e)
          cv::circle(figure, axes.to_image(e->x(), e->y()), 4, kColours.at(name), cv::FILLED,
                     cv::LINE_AA);
      }
    }
  }
  std::vector<LegendEntry> legend;
  for (const auto& [name, colour] : kColours) legend.push_back({name, colour});
  legend.push_back({"true ball (cross)", {0, 0, 0}});
  draw_legend(figure, {kMargin + 10, kPanel + kMargin + 50}, legend);
  return figure;
}

}  // namespace ballsight
