#pragma once
// The robot's last look before a command goes to the wheels, on the court's costmap
// (plan/costmap.hpp). After ROS 2 Nav2's Regulated Pure Pursuit (docs.nav2.org, "Regulated Pure
// Pursuit": use_collision_detection projects the commanded velocity forward and checks the
// footprint on the costmap) and, where that leaves the robot no way, its DWB controller's sampled
// trajectories scored by critics (docs.nav2.org, "DWB Controller"):
// - the wanted command is driven in imagination as the wheels would, from where the robot will be
//   when it acts (the collector predicts that pose over its latency): held for one update period,
//   then braked to a stop within the drive's limits. If the body's outline keeps `margin_m` from
//   every obstacle all the way, it goes as wanted;
// - else the same curvature slower (3/4, 1/2, 1/4 of the speeds): the first that keeps clear;
// - else, of a small set (back, creep and drive on; turning hard, gently or not), the command
//   that keeps the outline `contact_m` from the obstacles and brings the mouth nearest the carrot
//   and faces it best after two seconds, if one does better than standing; else the one that
//   takes the body farthest from the obstacles (alongside the net, where a turn on the spot
//   swings a corner into it, a gentle arc away);
// - else it stops.
// An outline already nearer than the margin (pose noise, a push) may move in any way that takes
// it no nearer. The costmap holds the net's mesh and posts and the fence; the route's planner
// keeps the mouth off them, this keeps the body's corners off them where the route's rules do not.

#include <optional>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/costmap.hpp"
#include "ballsight/robot/path_follower.hpp"

namespace ballsight {

/// The robot's body in its own frame (x forward from its reference point): a rectangle.
struct BodyOutline {
  double back_m = 0.30;  // the simulator's 0.60 m box, centred on the reference point
  double front_m = 0.30;
  double half_width_m = 0.35;  // the 0.70 m collector is wider than the 0.45 m box
};

struct LocalPlannerOptions {
  BodyOutline body;
  double margin_m = 0.015;      // the outline keeps this far from every obstacle
  double contact_m = 0.005;     // and a way out, where there is no other, this far
  double period_s = 0.1;        // a command is followed by the next one this much later
  double max_accel_mps2 = 1.0;  // braking
  double max_turn_accel_rps2 = 6.2831853071795862;  // 360 deg/s^2
  double max_speed_mps = 1.0;
  double max_turn_rate_rps = 1.5707963267948966;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// What the local planner made of a wanted command.
enum class Guard { as_wanted, slowed, replaced, stopped };

struct GuardedCommand {
  FollowCommand command;
  Guard guard = Guard::as_wanted;
};

class LocalPlanner {
 public:
  LocalPlanner(Costmap costmap, const LocalPlannerOptions& options);
  /// What stands on the court from now on (Costmap::set_obstacles).
  void set_obstacles(std::vector<ObstacleDisc> discs) { costmap_.set_obstacles(std::move(discs)); }

  /// The command to send for `wanted` at `pose`, with the mouth `mouth_ahead_m` ahead and
  /// steering for `carrot`.
  GuardedCommand guard(const Pose2D& pose, const FollowCommand& wanted, const Vec2& carrot,
                       double mouth_ahead_m);

  /// The nearest obstacle to the body's outline at `pose`, metres (negative: overlapping).
  double clearance(const Pose2D& pose) const;

 private:
  /// The command, driven as the wheels would until stopped, keeps the outline `limit_m` from the
  /// obstacles (or, starting nearer, no nearer than `start_clearance`).
  bool clear(const Pose2D& pose, const FollowCommand& command, double start_clearance,
             double limit_m) const;

  Costmap costmap_;
  LocalPlannerOptions options_;
  std::optional<FollowCommand> kept_;  // the replacement under way
  int kept_periods_ = 0;
};

}  // namespace ballsight
