#include "ballsight/viz/estimate_plot.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

// Estimates at `offset_cm` from the truth at each of two distances; one not found at the first.
EstimateLayer layer_at(const std::string& label, double offset_cm, bool one_missing = false) {
  const Vec2 truth(400, 600);
  EstimateLayer layer{label, cv::Scalar(200, 110, 0), {}};
  layer.estimates_cm.push_back({truth + Vec2(offset_cm, 0), truth - Vec2(0, offset_cm)});
  layer.estimates_cm.push_back({truth + Vec2(0, offset_cm)});
  if (one_missing) layer.estimates_cm[0].push_back(std::nullopt);
  return layer;
}

TEST(EstimatePlot, ARowOfZoomedPanelsOnlyWhenSomeButNotAllLayersAreClose) {
  const Vec2 truth(400, 600);
  const std::vector<int> distances{120, 200};
  const auto rows = [&](const std::vector<EstimateLayer>& layers) {
    const cv::Mat figure = plot_ball_estimates(truth, distances, layers);
    EXPECT_EQ(figure.cols, 2 * (420 + 70) + 70);
    return (figure.rows - 70 - 150) / (420 + 70 + 40);
  };
  EXPECT_EQ(rows({layer_at("close", 0.3), layer_at("far", 40.0)}), 2);
  EXPECT_EQ(rows({layer_at("close", 0.3), layer_at("also close", 1.0)}), 1);
  EXPECT_EQ(rows({layer_at("far", 40.0)}), 1);
  // A ball not found is no close estimate.
  EXPECT_EQ(rows({layer_at("close", 0.3, true), layer_at("far", 40.0)}), 1);
}

}  // namespace
}  // namespace ballsight
