#pragma once
// A closed loop's record as the data of the report's replay (web/loop_replay.js): the robot's
// true pose at every tick, each ball and when it was collected, and the routes the service
// published, each from the moment it was published until the next.

#include <nlohmann/json.hpp>

#include "ballsight/service/loop_truth.hpp"

namespace ballsight {

/// {"duration_s", "path": [[t_s, x_m, y_m, heading_deg], ...] (the start first, at 0),
/// "balls": [[x_m, y_m, collected_s or null], ...], "routes": [[t_s, [[x_m, y_m], ...]], ...]
/// (a route only when it differs from the one before)}.
nlohmann::json loop_replay_json(const LoopTruth& truth);

}  // namespace ballsight
