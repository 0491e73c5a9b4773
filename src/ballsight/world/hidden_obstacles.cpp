#include "ballsight/world/hidden_obstacles.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void HiddenObstacleOptions::validate() const {
  require(std::isfinite(near_robot_m) && near_robot_m >= 0.0, "hidden obstacles near_robot_m",
          "must not be negative");
  require(max_frame_sets >= 0, "hidden obstacles max_frame_sets", "must not be negative");
  require(std::isfinite(match_m) && match_m > 0.0, "hidden obstacles match_m", "must be positive");
}

HiddenObstacleMemory::HiddenObstacleMemory(const HiddenObstacleOptions& options)
    : options_(options) {
  options_.validate();
}

void HiddenObstacleMemory::apply(WorldModel& world) {
  const auto seen = [&](const FloorObstacle& o) {
    return std::any_of(world.obstacles.begin(), world.obstacles.end(), [&](const FloorObstacle& w) {
      return (w.center_m - o.center_m).norm() < options_.match_m;
    });
  };
  // With the robot not seen (a person beside it may hide its markers), what is remembered stays
  // for its time; nothing new is taken up.
  const auto near_robot = [&](const FloorObstacle& o, bool unseen_robot) {
    if (!world.robot) return unseen_robot;
    return (world.robot->pose.position - o.center_m).norm() - o.radius_m <= options_.near_robot_m;
  };
  std::vector<Remembered> kept;
  for (Remembered& r : remembered_) {
    if (!seen(r.obstacle) && near_robot(r.obstacle, true) &&
        ++r.frame_sets <= options_.max_frame_sets)
      kept.push_back(r);
  }
  for (const FloorObstacle& o : last_seen_) {
    if (!seen(o) && near_robot(o, false) && options_.max_frame_sets > 0) {
      FloorObstacle hidden = o;
      hidden.cameras.clear();
      kept.push_back({hidden, 1});
    }
  }
  last_seen_ = world.obstacles;
  remembered_ = std::move(kept);
  for (const Remembered& r : remembered_) world.obstacles.push_back(r.obstacle);
}

}  // namespace ballsight
