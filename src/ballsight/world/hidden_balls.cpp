#include "ballsight/world/hidden_balls.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void HiddenBallOptions::validate() const {
  require(std::isfinite(near_robot_m) && near_robot_m > 0.0, "near_robot_m", "must be positive");
  require(max_frame_sets >= 1, "max_frame_sets", "must be at least 1");
  require(std::isfinite(match_m) && match_m > 0.0, "match_m", "must be positive");
}

HiddenBallMemory::HiddenBallMemory(const HiddenBallOptions& options) : options_(options) {
  options_.validate();
}

void HiddenBallMemory::apply(WorldModel& world) {
  const auto near_any = [&](const Vec2& p, const auto& list, const auto& position) {
    return std::any_of(list.begin(), list.end(), [&](const auto& item) {
      return (position(item) - p).norm() < options_.match_m;
    });
  };
  const auto of_ball = [](const FusedBall& b) { return b.position_m; };
  const auto of_remembered = [](const Remembered& r) { return r.ball.position_m; };
  std::vector<Remembered> next;
  if (world.robot) {
    const Vec2& robot = world.robot->pose.position;
    const auto hidden = [&](const Vec2& p) {
      return (p - robot).norm() < options_.near_robot_m && !near_any(p, world.balls, of_ball);
    };
    for (const Remembered& r : remembered_) {
      if (r.frame_sets < options_.max_frame_sets && hidden(r.ball.position_m)) {
        next.push_back({r.ball, r.frame_sets + 1});
      }
    }
    for (const FusedBall& b : last_seen_) {
      if (hidden(b.position_m) && !near_any(b.position_m, next, of_remembered)) {
        next.push_back({b, 1});
        next.back().ball.cameras.clear();  // no camera sees it now
      }
    }
  }
  last_seen_ = world.balls;
  remembered_ = std::move(next);
  for (const Remembered& r : remembered_) {
    world.sites.push_back({r.ball.position_m, {static_cast<int>(world.balls.size())}, 0.0});
    world.balls.push_back(r.ball);
  }
}

}  // namespace ballsight
