#pragma once
// The world model as JSON, for `court run --json` (one object per frame set) and other tools.
// Units: metres and degrees, as the key names say.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ballsight/core/site_court.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

/// {"cameras": [...], "balls": [{"x_m", "y_m", "sigma_m", "cameras"}], "sites": [{"x_m", "y_m",
/// "diameter_m", "balls"}], "obstacles": [{"x_m", "y_m", "radius_m", "outline_m": [[x, y], ...],
/// "cameras"}], "robot": {"x_m", "y_m", "heading_deg", "position_sigma_m",
/// "heading_sigma_deg", "front_cameras", "back_cameras"} or null}. `camera_names` names the
/// camera indices.
nlohmann::json world_model_json(const WorldModel& world,
                                const std::vector<std::string>& camera_names);

/// What the court map of the web pages draws (web/court_map.js): {"length_m", "width_m",
/// "area_length_m", "area_width_m", "net", "net_posts_outside_m"}.
nlohmann::json site_court_json(const SiteCourt& court);

}  // namespace ballsight
