#pragma once
// A fitted omni model baked into ballsight's lookup table (camera/ground_map.hpp): one cell per
// pixel of the model's image, valid over the model's valid radius range.

#include "ballsight/calib/omni_ground_model.hpp"
#include "ballsight/camera/ground_map.hpp"

namespace ballsight {

/// The table header for a model: its image, centre, valid range and method name.
GroundMapInfo ground_map_info(const OmniGroundModel& model);

/// Every pixel's robot-local ground point (cm) from the model; invalid outside its range.
GroundMap ground_map_from_model(const OmniGroundModel& model);

}  // namespace ballsight
