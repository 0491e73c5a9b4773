#pragma once
// A navigation update as the robot's HTTP client (http_robot_link.hpp) reads it off the network:
// the JSON of API v1 (navigation_json in api.hpp) back into the values a controller drives by.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/robot/robot_link.hpp"

namespace ballsight {

/// Throws InputError naming the field when `update` is not a navigation update.
LinkUpdate parse_link_update(const nlohmann::json& update);

}  // namespace ballsight
