#pragma once
// A navigation update as the robot's client (robot_link.hpp) reads it off the network: the JSON
// of API v1 (navigation_json in api.hpp) back into the values a controller drives by.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// One navigation update as the robot needs it.
struct LinkUpdate {
  std::uint64_t seq = 0;
  std::string service_id;
  std::int64_t capture_time_ns = 0;
  std::int64_t published_ns = 0;
  std::int64_t received_ns = 0;  // UTC, when this client had it
  std::optional<Pose2D> robot;   // the robot as the cameras saw it
  std::vector<Vec2> balls_m;
  std::vector<Vec2> visits_m;     // where the collector passes, in order
  std::vector<Vec2> waypoints_m;  // the path to drive
  nlohmann::json raw;             // the whole update
};

/// Throws InputError naming the field when `update` is not a navigation update.
LinkUpdate parse_link_update(const nlohmann::json& update);

}  // namespace ballsight
