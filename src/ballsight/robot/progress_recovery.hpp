#pragma once
// Noticing that the robot is stuck and freeing it, after ROS 2 Nav2's progress checker and
// recovery behaviours (docs.nav2.org: SimpleProgressChecker's required_movement_radius 0.5 m
// within movement_time_allowance 10 s; BackUp, then the route again). A robot with balls left
// that has neither moved 0.5 m nor turned 45 degrees in 10 s is stalled (pressed against the net
// by a turn on the spot, or standing at a route's end short of a ball): it backs straight up
// 0.3 m, or, when it cannot (it has not moved 5 cm in 2 s), drives 0.3 m straight ahead, and then
// follows its route again, which the new place usually opens.

#include <optional>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/robot/path_follower.hpp"

namespace ballsight {

struct ProgressOptions {
  double window_s = 10.0;       // Nav2's movement_time_allowance
  double radius_m = 0.5;        // Nav2's required_movement_radius
  double turn_rad = kPi / 4.0;  // or this much turning: a turn on the spot is progress too
  double recovery_m = 0.3;      // each recovery drives this far straight
  double recovery_speed_mps = 0.3;
  double recovery_s = 2.0;  // in one direction at most this long
  double stuck_m = 0.05;    // moved less in that time: that way is blocked

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class ProgressRecovery {
 public:
  explicit ProgressRecovery(const ProgressOptions& options = {});

  /// The robot is at `pose` at `now_s` (seconds on any steady clock); `working`: it has balls
  /// left to collect. Nullopt: follow the route; else the recovery's command.
  std::optional<FollowCommand> step(const Pose2D& pose, double now_s, bool working);

  /// Forgets the window under way (its clock changes): the next step begins a new one.
  void restart();

  /// Times the robot was found stalled.
  int stalls() const { return stalls_; }
  /// Recovery behaviours begun: a back-up for each stall, and a drive ahead where backing was
  /// blocked.
  int recoveries() const { return recoveries_; }

 private:
  enum class Phase { watching, backing, forward };

  void start(Phase phase, const Pose2D& pose, double now_s);
  /// The command of the recovery's phase: straight back, or straight ahead.
  FollowCommand drive() const;

  ProgressOptions options_;
  Phase phase_ = Phase::watching;
  std::optional<Pose2D> since_;  // where the window (or the recovery's phase) began
  double since_s_ = 0.0;
  int stalls_ = 0;
  int recoveries_ = 0;
};

}  // namespace ballsight
