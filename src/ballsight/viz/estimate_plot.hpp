#pragma once
// Where methods placed one ball, seen from above around the true ball: a panel per robot distance
// with every estimate of every method, and a row of zoomed panels for the methods whose every
// estimate lies close (`ballsight eval omni --plot`; eval/plot_inputs.hpp reads the omni
// experiment's results into EstimateLayers).

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// One method's estimates, drawn in one colour.
struct EstimateLayer {
  std::string label;
  cv::Scalar colour;
  /// Per robot distance of the plot (in its order), the estimates; nullopt: not found.
  std::vector<std::vector<std::optional<Vec2>>> estimates_cm;
};

/// The panels of every estimate around `truth_cm` (field cm), one per distance of
/// `distances_cm`, one colour per layer.
cv::Mat plot_ball_estimates(const Vec2& truth_cm, const std::vector<int>& distances_cm,
                            const std::vector<EstimateLayer>& layers);

}  // namespace ballsight
