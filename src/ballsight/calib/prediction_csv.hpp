#pragma once
// A model's predictions for calibration samples as CSV: the sample columns, then
// predicted_distance_cm, predicted_bearing_deg (empty when the model takes the image direction)
// and in_range (0/1).

#include <span>
#include <string>

#include "ballsight/calib/omni_ground_model.hpp"

namespace ballsight {

std::string format_prediction_csv(const OmniGroundModel& model,
                                  std::span<const PolarSample> samples);

}  // namespace ballsight
