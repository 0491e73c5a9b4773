#pragma once
// The simulated collector's truth: a differential-drive robot that speeds up, turns and stops
// within its limits, cannot pass through the net or the fence, and picks up every tennis ball
// its collector mouth reaches (the tennis-ball report's 70 cm collector, section 7.8).

#include <span>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

struct DriveLimits {
  double max_speed_mps = 1.0;
  double max_accel_mps2 = 1.0;      // speeding up and braking
  double max_turn_rate_dps = 90.0;  // turning on the spot
  double max_turn_accel_dps2 = 360.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// What a real collector does that its commands do not say; the defaults are a perfect robot.
struct RobotImperfections {
  double command_latency_s = 0.0;  // a command acts this long after it was given
  /// Wheel slip: a share of the wheels' motion (forward and turn, each its own) that the robot
  /// does not make over the ground, varying slowly about 0 with this standard deviation, so that
  /// odometry from the wheels is off by about this fraction of a drive of a metre or two (over
  /// longer drives the slip partly averages out).
  double odometry_drift = 0.0;
  double slip_time_s = 2.0;  // how long a slip lasts (its correlation time)
  std::uint64_t seed = 1;    // of the slip

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Wheel speeds as forward speed and turn rate (rad/s, counter-clockwise).
struct DriveCommand {
  double speed_mps = 0.0;
  double turn_rate_rps = 0.0;
};

struct RobotMotion {
  Pose2D pose;  // the box centre, as RobotBox::pose
  double speed_mps = 0.0;
  double turn_rate_rps = 0.0;
};

/// What the robot occupies, in its own frame (x forward): its box and the collector's mouth.
struct RobotFootprint {
  double back_m = 0.30;
  double front_m = 0.30;
  double half_width_m = 0.35;   // the collector is wider than the box
  double collector_x_m = 0.30;  // the mouth, ahead of the pose
  double collector_width_m = 0.70;

  /// The footprint of `box` with a collector of this width, its mouth this far ahead.
  static RobotFootprint of(const RobotBox& box, double collector_x_m, double collector_width_m);
};

/// Whether the robot at `pose` overlaps the net (its mesh between the posts, and the posts), one
/// of the `obstacles` or reaches beyond the fenced area.
bool footprint_blocked(const RobotFootprint& footprint, const Pose2D& pose,
                       const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles = {});

/// How far the robot at `pose` is from the net, the fence and the `obstacles` (the nearest of its
/// footprint's points to any), exactly; 0 where it overlaps one (footprint_blocked).
double footprint_clearance(const RobotFootprint& footprint, const Pose2D& pose,
                           const TennisCourtSpec& court,
                           std::span<const CourtObstacle> obstacles = {});

/// Whether the collector's mouth can be put over a ball at `ball` with no part of the robot in
/// the net, an obstacle or beyond the fence: some heading (every 5 degrees) and some place of the
/// ball across the mouth (every 2 cm, the ball wholly inside it) where the footprint is clear.
/// The court's free space is one piece (round the posts; the scenarios keep obstacles apart
/// from the net and the fence), so such a pose can be driven to.
bool mouth_can_reach(const RobotFootprint& footprint, const Vec2& ball, double ball_radius_m,
                     const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles = {});

struct DriveStep {
  RobotMotion motion;
  bool blocked = false;  // the net or the fence was in the way of the commanded motion
};

/// Wheel slip: the share of the wheels' motion that the robot does not make over the ground.
struct Slip {
  double speed = 0.0;  // of the forward motion
  double turn = 0.0;   // of the turn
};

/// One step of `dt` seconds: speed and turn rate (the wheels') move towards the command within
/// the limits, the pose follows the arc they describe, less the `slip`. Where that would put the
/// footprint into the net, the fence or an obstacle, the robot only slides straight on, or only
/// turns on the spot, whichever is clear, or stops: it never overlaps them.
DriveStep drive_step(const RobotMotion& motion, const DriveCommand& command, double dt,
                     const DriveLimits& limits, const RobotFootprint& footprint,
                     const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles = {},
                     const Slip& slip = {});

/// Removes from `scene` the tennis balls the collector's mouth reached while the robot moved from
/// `before` to `after` (forwards, within the mouth's width): the mouth touched the ball (its
/// centre came within a radius of the mouth's line), as a roller takes it in; their ids. At most
/// `room` are taken (a full basket's collector passes over the rest).
std::vector<int> collect_swept(CourtScene& scene, const Pose2D& before, const Pose2D& after,
                               const RobotFootprint& footprint,
                               std::size_t room = static_cast<std::size_t>(-1));

}  // namespace ballsight::sim
