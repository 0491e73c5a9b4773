#include "ballsight/viz/estimate_plot.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "ballsight/viz/chart.hpp"

namespace ballsight {

namespace {
// Below this error every estimate of a layer also gets a zoomed panel (cm).
constexpr double kZoomBelowCm = 5.0;
}  // namespace

cv::Mat plot_ball_estimates(const Vec2& truth_cm, const std::vector<int>& distances_cm,
                            const std::vector<EstimateLayer>& layers) {
  // Row 0: every layer; row 1: the layers whose estimates all lie within kZoomBelowCm.
  std::vector<const EstimateLayer*> all, precise;
  for (const EstimateLayer& layer : layers) {
    all.push_back(&layer);
    bool close = true;
    for (const auto& estimates : layer.estimates_cm)
      for (const auto& e : estimates) close = close && e && (*e - truth_cm).norm() < kZoomBelowCm;
    if (close) precise.push_back(&layer);
  }
  std::vector<std::vector<const EstimateLayer*>> rows = {all};
  if (!precise.empty() && precise.size() < all.size()) rows.push_back(precise);

  constexpr int kPanel = 420, kMargin = 70;
  const int row_height = kPanel + kMargin + 40;  // room for the x label above the next title
  cv::Mat figure(static_cast<int>(rows.size()) * row_height + kMargin + 150,
                 static_cast<int>(distances_cm.size()) * (kPanel + kMargin) + kMargin, CV_8UC3,
                 cv::Scalar(255, 255, 255));
  for (size_t row = 0; row < rows.size(); ++row) {
    for (size_t i = 0; i < distances_cm.size(); ++i) {
      // A square window around the true ball wide enough for every estimate of this row.
      double extent = row == 0 ? 5.0 : 0.5;
      for (const EstimateLayer* layer : rows[row])
        for (const auto& e : layer->estimates_cm.at(i))
          if (e) extent = std::max(extent, (*e - truth_cm).cwiseAbs().maxCoeff() * 1.1);
      extent = nice_ceil(extent);
      ChartAxes axes{cv::Rect(kMargin + static_cast<int>(i) * (kPanel + kMargin),
                              kMargin + static_cast<int>(row) * row_height, kPanel, kPanel),
                     truth_cm.x() - extent, truth_cm.x() + extent, truth_cm.y() - extent,
                     truth_cm.y() + extent};
      draw_axes(figure, axes, "field x (cm)", "field y (cm)",
                "robot " + std::to_string(distances_cm[i]) + " cm from the ball" +
                    (row == 0 ? "" : " (zoomed)"));
      cv::drawMarker(figure, axes.to_image(truth_cm.x(), truth_cm.y()), {0, 0, 0}, cv::MARKER_CROSS,
                     18, 2);
      for (const EstimateLayer* layer : rows[row]) {
        for (const auto& e : layer->estimates_cm.at(i)) {
          if (e)
            cv::circle(figure, axes.to_image(e->x(), e->y()), row == 0 ? 4 : 3, layer->colour,
                       cv::FILLED, cv::LINE_AA);
        }
      }
    }
  }
  std::vector<LegendEntry> legend;
  for (const EstimateLayer* layer : all) legend.push_back({layer->label, layer->colour});
  legend.push_back({"true ball (cross)", {0, 0, 0}});
  draw_legend(figure, {kMargin + 10, static_cast<int>(rows.size()) * row_height + kMargin + 20},
              legend);
  return figure;
}

}  // namespace ballsight
