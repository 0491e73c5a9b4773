#pragma once
// One navigation update as JSON: what API v1 sends (GET /api/v1/navigation, the stream), what
// Foxglove's /navigation channel carries and what a recording keeps.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ballsight/service/navigation_hub.hpp"

namespace ballsight {

/// {"seq", "service_id", "capture_time_ns", "published_ns", "world": {...}, "route": {...},
/// "given_up": [{"x_m", "y_m", "reason"}]}; `camera_names` names the world's camera indices.
nlohmann::json navigation_json(const NavigationUpdate& update, const std::string& service_id,
                               const std::vector<std::string>& camera_names);

/// What clients reported (ClientReports): {"robot": {"x_m", "y_m", "heading_rad", "set_ns"} or
/// null, "balls": {"count", "m": [[x, y], ...], "set_ns"} or null, "collected": [[x, y], ...],
/// "basket": {"held", "set_ns"} or null, "unreachable": [{"x_m", "y_m", "reason"}]}.
nlohmann::json client_reports_json(const ClientReports& reports);
/// client_reports_json's inverse. Throws nlohmann::json::exception for a document of another
/// shape.
ClientReports parse_client_reports(const nlohmann::json& json);

}  // namespace ballsight
