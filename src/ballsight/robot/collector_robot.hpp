#pragma once
// The simulated collector's controller (`ballsight robot`, `eval loop`): for every navigation
// update it steers the collector's mouth along the route (path_follower.hpp), sends its
// wheels' command to the simulated court (PUT /api/v1/sim/drive), acknowledges the update and
// reports the balls its collector took (the collector's sensor counts them; they were at its
// mouth). It knows only what the service sends and its wheels' odometry, by which it carries its
// pose on where the cameras do not see it (pose_tracker.hpp), and tells the service that pose. A
// robot with balls left that makes no progress frees itself (progress_recovery.hpp), on the
// simulated court's clock when it drives there, else on its own. Its basket: when the route
// empties it first (the basket is full, or the next balls would not fit), the robot drives to
// the unload point the update names and stands there, mouth over it, until the basket is empty;
// it tells the service how many balls its basket holds (the simulated court's answer says) with
// every report of collected balls, and again until the service has it (basket_tracker.hpp).
// A ball it stalls on the way to `give_up_after` times, with no ball collected between, it marks
// unreachable, with why; the service plans the rest without it, and the robot counts it no more
// among the balls left.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ballsight/plan/drivable_court.hpp"
#include "ballsight/robot/basket_tracker.hpp"
#include "ballsight/robot/local_planner.hpp"
#include "ballsight/robot/path_follower.hpp"
#include "ballsight/robot/pose_tracker.hpp"
#include "ballsight/robot/progress_recovery.hpp"
#include "ballsight/robot/robot_link.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

/// The follower for a site's robot and court: its mouth, speeds, and the net's lane to back off.
FollowerOptions follower_for_site(const Site& site);
/// The local planner for a site's robot: its body (the collector's width; the simulator's box),
/// speeds and braking.
LocalPlannerOptions local_planner_for_site(const Site& site);

struct CollectorOptions {
  FollowerOptions follow = follower_for_site(Site{});  // mouth 0.30 m ahead, 1 m/s, 90 deg/s
  /// Every command passes the local planner on the court's costmap (local_planner.hpp).
  LocalPlannerOptions local = local_planner_for_site(Site{});
  DrivableCourt court = drivable_court(SiteCourt{});
  int done_after = 10;      // updates in a row with no ball and no route: all collected
  double max_time_s = 0.0;  // wall time; 0: no limit
  /// From the frames' capture to the wheels acting on the command sent for them: the robot
  /// steers from where it will be then, the cameras' pose moved on by the command the wheels
  /// carry out meanwhile (the last one sent; a Smith predictor for a latency of up to one
  /// update period). 0: it steers from the cameras' pose.
  double latency_s = 0.0;
  ProgressOptions progress;  // when it is stalled and how it frees itself
  PoseTrackerOptions pose;   // how far it drives on its own estimate out of the cameras' sight
  int give_up_after = 3;     // stalls on the way to the same ball before it is marked unreachable
  BasketOptions basket;      // the stop to empty the basket

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct CollectorResult {
  bool done = false;  // stopped because no ball was left (not by time or `stop`)
  int updates = 0;
  int collected = 0;      // as the collector's sensor counted them
  int stalls = 0;         // times it was stalled and backed up (or drove ahead) to free itself
  int recoveries = 0;     // recovery behaviours begun (a back-up, a drive ahead)
  int dead_reckoned = 0;  // frame sets on which the cameras did not see it and it drove on its
                          // own estimate (pose_tracker.hpp)
  int guarded = 0;        // commands the local planner slowed, replaced or stopped
  int unloads = 0;        // times it emptied its basket
  int unreachable = 0;    // balls it gave up on
  std::uint64_t gaps = 0;
  int reconnects = 0;
  double sim_time_s = 0.0;  // the simulated court's clock at the last command
  /// Per update, in arrival order: frames captured -> update parsed here (wall ms, UTC clocks
  /// of one machine), and its sequence number.
  std::vector<double> latency_ms;
  std::vector<std::uint64_t> seqs;
};

/// Drives until done, `stop`, or the time limit; `progress` hears a line every 100 updates.
CollectorResult run_collector(RobotLink& link, const CollectorOptions& options,
                              const std::atomic<bool>& stop,
                              const std::function<void(const std::string&)>& progress = {});

}  // namespace ballsight
