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
                                                    {"ballsight-auto", {60, 170, 40}},
                                                    {"oracle", {60, 60, 60}}};
}  // namespace

// Below this error every estimate of a method also gets a zoomed panel (cm).
constexpr double kZoomBelowCm = 5.0;

cv::Mat plot_omni_experiment(const OmniExperimentResult& result) {
  const std::map<std::string, OmniMethodResult>& methods = result.methods;
  std::vector<int> distances = result.options.distances_cm;
  const Vec2 truth = result.options.ball_cm;
  // Row 0: every method; row 1: the methods whose estimates all lie within kZoomBelowCm.
  std::vector<std::string> all, precise;
  for (const auto& [name, method] : methods) {
    if (method.by_distance.empty()) continue;  // not calibrated
    all.push_back(name);
    bool close = true;
    for (const auto& [distance, r] : method.by_distance)
      for (const auto& e : r.estimates_cm) close = close && e && (*e - truth).norm() < kZoomBelowCm;
    if (close) precise.push_back(name);
  }
  std::vector<std::vector<std::string>> rows = {all};
  if (!precise.empty() && precise.size() < all.size()) rows.push_back(precise);

  constexpr int kPanel = 420, kMargin = 70;
  const int row_height = kPanel + kMargin + 40;  // room for the x label above the next title
  cv::Mat figure(static_cast<int>(rows.size()) * row_height + kMargin + 150,
                 static_cast<int>(distances.size()) * (kPanel + kMargin) + kMargin, CV_8UC3,
                 cv::Scalar(255, 255, 255));
  for (size_t row = 0; row < rows.size(); ++row) {
    for (size_t i = 0; i < distances.size(); ++i) {
      // A square window around the true ball wide enough for every estimate of this row.
      double extent = row == 0 ? 5.0 : 0.5;
      for (const std::string& name : rows[row])
        for (const auto& e : methods.at(name).by_distance.at(distances[i]).estimates_cm)
          if (e) extent = std::max(extent, (*e - truth).cwiseAbs().maxCoeff() * 1.1);
      extent = nice_ceil(extent);
      ChartAxes axes{cv::Rect(kMargin + static_cast<int>(i) * (kPanel + kMargin),
                              kMargin + static_cast<int>(row) * row_height, kPanel, kPanel),
                     truth.x() - extent, truth.x() + extent, truth.y() - extent,
                     truth.y() + extent};
      draw_axes(figure, axes, "field x (cm)", "field y (cm)",
                "robot " + std::to_string(distances[i]) + " cm from the ball" +
                    (row == 0 ? "" : " (zoomed)"));
      cv::drawMarker(figure, axes.to_image(truth.x(), truth.y()), {0, 0, 0}, cv::MARKER_CROSS, 18,
                     2);
      for (const std::string& name : rows[row]) {
        for (const auto& e : methods.at(name).by_distance.at(distances[i]).estimates_cm) {
          if (e)
            cv::circle(figure, axes.to_image(e->x(), e->y()), row == 0 ? 4 : 3, kColours.at(name),
                       cv::FILLED, cv::LINE_AA);
        }
      }
    }
  }
  std::vector<LegendEntry> legend;
  for (const std::string& name : all) legend.push_back({name, kColours.at(name)});
  legend.push_back({"true ball (cross)", {0, 0, 0}});
  draw_legend(figure, {kMargin + 10, static_cast<int>(rows.size()) * row_height + kMargin + 20},
              legend);
  return figure;
}

}  // namespace ballsight
