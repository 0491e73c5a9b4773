#include "ballsight/world/hidden_balls.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void HiddenBallOptions::validate() const {
  require(std::isfinite(near_robot_m) && near_robot_m > 0.0, "near_robot_m", "must be positive");
  require(max_frame_sets >= 1, "max_frame_sets", "must be at least 1");
  require(std::isfinite(match_m) && match_m > 0.0, "match_m", "must be positive");
  require(std::isfinite(mouth_ahead_m) && std::isfinite(taken_within_m) && taken_within_m >= 0.0,
          "taken_within_m", "must be a non-negative number");
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
    const Pose2D& pose = world.robot->pose;
    const Vec2& robot = pose.position;
    const Vec2 mouth = pose.ahead(options_.mouth_ahead_m);
    const auto hidden = [&](const Vec2& p) {
      return (p - robot).norm() < options_.near_robot_m && !near_any(p, world.balls, of_ball);
    };
    for (const Remembered& r : state_.remembered) {
      if (r.frame_sets < options_.max_frame_sets && hidden(r.ball.position_m)) {
        next.push_back({r.ball, r.frame_sets + 1});
      }
    }
    for (const FusedBall& b : state_.last_seen) {
      if (hidden(b.position_m) && (b.position_m - mouth).norm() > options_.taken_within_m &&
          !near_any(b.position_m, next, of_remembered)) {
        next.push_back({b, 1});
        next.back().ball.cameras.clear();  // no camera sees it now
      }
    }
  }
  state_.last_seen = world.balls;
  state_.remembered = std::move(next);
  for (const Remembered& r : state_.remembered) {
    world.sites.push_back({r.ball.position_m, {static_cast<int>(world.balls.size())}, 0.0});
    world.balls.push_back(r.ball);
  }
}

}  // namespace ballsight
