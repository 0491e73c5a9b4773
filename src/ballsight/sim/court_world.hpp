#pragma once
// The simulated court in time: the scene, the collector driving in it (robot_motion.hpp), the
// simulated clock and the record of what really happened, so that a run can be scored afterwards.

#include <cmath>
#include <cstdint>
#include <deque>
#include <random>
#include <utility>
#include <vector>

#include "ballsight/sim/robot_motion.hpp"

namespace ballsight::sim {

/// One advance of the world: when it ended, where the robot really was, what it collected.
struct WorldTick {
  double time_s = 0.0;
  Pose2D robot;
  std::vector<int> collected;  // tennis ball ids collected during this advance
  int balls_left = 0;
  bool blocked = false;  // the net, the fence or an obstacle stopped the robot during it
  /// The wheels' odometry at its end: the pose the wheels' turns add up to, slip not seen, in
  /// the odometry's own frame (the robot's pose when the world began, or resumed).
  Pose2D odometry;
  int held = 0;           // balls in the basket at its end
  bool unloaded = false;  // the basket was emptied during it
  /// The body's nearest approach to the net, the fence or an obstacle during it (NaN: not known,
  /// a record written before obstacles).
  double clearance_m = NAN;
};

/// The collector's basket: it holds `capacity` balls (0: no limit), and is emptied when the
/// robot has stood still for `unload_s` with its mouth within `reach_m` of `unload_m`.
struct CollectorBasket {
  int capacity = 0;
  Vec2 unload_m = Vec2::Zero();
  double unload_s = 5.0;
  double reach_m = 0.5;
};

class CourtWorld {
 public:
  CourtWorld(CourtScene scene, const TennisCourtSpec& court, const DriveLimits& limits,
             const RobotFootprint& footprint, const RobotImperfections& imperfections = {},
             const CollectorBasket& basket = {});

  const CourtScene& scene() const { return scene_; }
  const RobotMotion& motion() const { return motion_; }
  /// The wheels' odometry now (WorldTick::odometry).
  const Pose2D& odometry() const { return odometry_; }
  double time_s() const { return time_s_; }
  int balls_left() const;
  const std::vector<WorldTick>& history() const { return history_; }

  /// Drives for `seconds` in steps of kStepS (the robot's box moves with it), `command` acting
  /// from the imperfections' command latency on (the commands given before it until then);
  /// records and returns the tick.
  const WorldTick& advance(const DriveCommand& command, double seconds);
  /// Continues a run recorded earlier: the clock at `time_s`, the robot standing at `pose`, the
  /// tennis balls `collected` gone, `held` of them in the basket.
  void resume(double time_s, const Pose2D& pose, const std::vector<int>& collected, int held);
  /// Balls in the basket now.
  int held() const { return held_; }
  /// Removes the tennis balls for which `taken` holds (a hand picking them up, as in the
  /// report's own test); their ids.
  template <class Pred>
  std::vector<int> remove_balls_if(Pred taken) {
    std::vector<int> ids;
    std::erase_if(scene_.balls, [&](const SceneSphere& b) {
      const bool t = b.kind == ObjectKind::tennis_ball && taken(b);
      if (t) ids.push_back(b.id);
      return t;
    });
    return ids;
  }

  static constexpr double kStepS = 0.01;
  /// A walking person stands still while its centre is this near the robot's (and the robot's
  /// body not yet touching it), though not on a ball: people wait for a robot to pass.
  static constexpr double kWalkerWaitM = 1.5;

 private:
  /// One step of every walking person (CourtObstacle::walk_to).
  void walk_step();
  /// One step's emptying: the robot still at the unload point with balls in the basket; true
  /// when the basket was emptied in it.
  bool unloading_step();

  CourtScene scene_;
  TennisCourtSpec court_;
  DriveLimits limits_;
  RobotFootprint footprint_;
  RobotImperfections imperfections_;
  CollectorBasket basket_;
  int held_ = 0;
  double standing_s_ = 0.0;  // at the unload point, still, with balls in the basket
  RobotMotion motion_;
  Pose2D odometry_;
  double time_s_ = 0.0;
  std::deque<std::pair<double, DriveCommand>> pending_;  // commands given, when each acts
  DriveCommand acting_;
  Slip slip_;
  std::mt19937_64 rng_;
  std::vector<WorldTick> history_;
  std::vector<Vec2> walk_from_;    // per obstacle: where its walk began
  std::vector<bool> walking_out_;  // per obstacle: on its way to walk_to
};

}  // namespace ballsight::sim
