#pragma once
// A planned route as JSON, for `ballsight plan --json` and the navigation service. Units: metres,
// seconds and milliseconds, as the key names say.

#include <nlohmann/json.hpp>

#include "ballsight/plan/planning_problem.hpp"

namespace ballsight {

/// {"planner", "order": [ball indices, 0-based], "visits_m": [[x, y], ..], "waypoints_m": [[x, y],
/// ..], "unload_after": [positions in order], "unreachable": [ball indices], "length_m",
/// "time_s", "plan_ms"}.
nlohmann::json route_json(const Route& route);

}  // namespace ballsight
