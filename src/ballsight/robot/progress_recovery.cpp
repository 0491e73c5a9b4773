#include "ballsight/robot/progress_recovery.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

void ProgressOptions::validate() const {
  for (const auto& [value, name] :
       {std::pair{window_s, "window_s"}, std::pair{radius_m, "radius_m"},
        std::pair{turn_rad, "turn_rad"}, std::pair{recovery_m, "recovery_m"},
        std::pair{recovery_speed_mps, "recovery_speed_mps"}, std::pair{recovery_s, "recovery_s"},
        std::pair{stuck_m, "stuck_m"}}) {
    require(std::isfinite(value) && value > 0.0, name, "must be positive");
  }
}

ProgressRecovery::ProgressRecovery(const ProgressOptions& options) : options_(options) {
  options_.validate();
}

void ProgressRecovery::start(Phase phase, const Pose2D& pose, double now_s) {
  phase_ = phase;
  since_ = pose;
  since_s_ = now_s;
  if (phase != Phase::watching) ++recoveries_;
}

void ProgressRecovery::restart() {
  phase_ = Phase::watching;
  since_.reset();
}

FollowCommand ProgressRecovery::drive() const {
  const double speed = options_.recovery_speed_mps;
  return {phase_ == Phase::backing ? -speed : speed, 0.0, false};
}

std::optional<FollowCommand> ProgressRecovery::step(const Pose2D& pose, double now_s,
                                                    bool working) {
  // A new window at the first step, and when the clock went back (a court resumed).
  if (!since_ || now_s < since_s_) start(Phase::watching, pose, now_s);
  const double moved = (pose.position - since_->position).norm();
  const double elapsed = now_s - since_s_;
  if (phase_ == Phase::watching) {
    if (!working || moved >= options_.radius_m ||
        std::abs(wrap_rad_pi(pose.heading_rad - since_->heading_rad)) >= options_.turn_rad) {
      start(Phase::watching, pose, now_s);
      return std::nullopt;
    }
    if (elapsed < options_.window_s) return std::nullopt;
    ++stalls_;
    start(Phase::backing, pose, now_s);
    return drive();
  }
  if (moved < options_.recovery_m && elapsed < options_.recovery_s) return drive();
  if (phase_ == Phase::backing && moved < options_.stuck_m) {  // blocked behind: ahead instead
    start(Phase::forward, pose, now_s);
    return drive();
  }
  start(Phase::watching, pose, now_s);  // recovered: the route again, a new window
  return std::nullopt;
}

}  // namespace ballsight
