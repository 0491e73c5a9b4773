#include "ballsight/robot/collector_robot.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/plan/drivable_court.hpp"
#include "ballsight/robot/basket_tracker.hpp"

namespace ballsight {
namespace {

constexpr double kUpdatePeriodS = 0.1;  // the cameras' 10 Hz, until the court's clock tells

constexpr double kSameBallM = 0.3;  // a ball seen this near a mark is the ball marked

/// The stalls on the way to one ball, with no ball collected between them: after `give_up_after`
/// of them it is unreachable.
class Tries {
 public:
  explicit Tries(int give_up_after) : give_up_after_(give_up_after) {}

  /// A stall on the way to the first visit of update `u`'s route: the ball it is for (the one
  /// seen nearest the visit) once it has had its tries (again at every stall until reset()).
  std::optional<Vec2> stalled(const LinkUpdate& u) {
    if (u.unload_first_m || u.visits_m.empty() || u.balls_m.empty()) return std::nullopt;
    const Vec2& visit = u.visits_m.front();
    const Vec2 ball = *std::min_element(
        u.balls_m.begin(), u.balls_m.end(),
        [&](const Vec2& a, const Vec2& b) { return (a - visit).norm() < (b - visit).norm(); });
    tries_ = tries_ > 0 && (ball_ - ball).norm() < kSameBallM ? tries_ + 1 : 1;
    ball_ = ball;
    return tries_ >= give_up_after_ ? std::optional<Vec2>(ball) : std::nullopt;
  }
  /// A ball was collected, or the one given up on was marked: the count begins again.
  void reset() { tries_ = 0; }

 private:
  int give_up_after_;
  int tries_ = 0;  // stalls on the way to ball_ (0: none yet)
  Vec2 ball_ = Vec2::Zero();
};

/// The balls seen that this robot has not given up on.
int balls_left(const LinkUpdate& u, const std::vector<Vec2>& given_up) {
  return static_cast<int>(std::count_if(u.balls_m.begin(), u.balls_m.end(), [&](const Vec2& b) {
    return std::none_of(given_up.begin(), given_up.end(),
                        [&](const Vec2& g) { return (g - b).norm() < kSameBallM; });
  }));
}

}  // namespace

FollowerOptions follower_for_site(const Site& site) {
  FollowerOptions f;
  f.mouth_ahead_m = site.robot.collector_x_m;
  f.max_speed_mps = site.robot.max_speed_mps;
  f.max_turn_rate_rps = rad_from_deg(site.robot.turn_rate_dps);
  const DrivableCourt court = drivable_court(site.court);
  if (court.net) f.back_off_zone = court.net->lane();
  f.fence = FieldRect{court.area_min_m, court.area_max_m};
  const Vec2 lane = Vec2::Constant(court.fence_lane_m);
  f.inside_fence_lane = FieldRect{court.area_min_m + lane, court.area_max_m - lane};
  return f;
}

LocalPlannerOptions local_planner_for_site(const Site& site) {
  LocalPlannerOptions l;
  const BodyOutline box;  // the simulator's box with the site's collector
  l.body.front_m = std::max(box.front_m, site.robot.collector_x_m);
  l.body.half_width_m = std::max(box.half_width_m, site.robot.collector_width_m / 2.0);
  l.max_accel_mps2 = site.robot.max_accel_mps2;
  l.max_turn_accel_rps2 = rad_from_deg(site.robot.turn_accel_dps2);
  l.max_speed_mps = site.robot.max_speed_mps;
  l.max_turn_rate_rps = rad_from_deg(site.robot.turn_rate_dps);
  return l;
}

void CollectorOptions::validate() const {
  follow.validate();
  local.validate();
  court.validate();
  require(done_after >= 1, "done_after", "must be at least 1");
  require(std::isfinite(max_time_s) && max_time_s >= 0.0, "max_time_s", "must not be negative");
  require(std::isfinite(latency_s) && latency_s >= 0.0 && latency_s <= 5.0, "latency_s",
          "must be in [0, 5] s");
  require(give_up_after >= 1, "give_up_after", "must be at least 1 stall");
  basket.validate();
  progress.validate();
  pose.validate();
}

CollectorResult run_collector(RobotLink& link, const CollectorOptions& options,
                              const std::atomic<bool>& stop,
                              const std::function<void(const std::string&)>& progress) {
  options.validate();
  PathFollower follower(options.follow);
  LocalPlanner local(Costmap(options.court), options.local);
  std::vector<Vec2> planned;  // the route's waypoints being followed
  FollowCommand sent;         // the last command sent
  // The command the wheels carry out during the latency: the last one sent for earlier frames (an
  // update published again for the same frames, after a report, replaces its command at once).
  FollowCommand in_flight;
  std::int64_t frames_ns = -1;
  ProgressRecovery recovery(options.progress);
  PoseTracker tracker(options.pose);
  bool told_pose = false;            // the service has this robot's own estimate since the last fix
  double period_s = kUpdatePeriodS;  // between the last two frame sets, on the court's clock
  bool sim_clock = false;            // the simulated court tells its time: stalls are timed on it
  CollectorResult result;
  Tries tries(options.give_up_after);
  std::vector<Vec2> given_up;  // balls this robot marked unreachable
  BasketTracker basket(options.basket);
  int empty = 0;
  const auto started = std::chrono::steady_clock::now();
  while (!stop) {
    if (options.max_time_s > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
            options.max_time_s) {
      break;
    }
    const std::optional<LinkUpdate> u = link.next(std::chrono::milliseconds(500));
    if (!u) continue;
    ++result.updates;
    result.latency_ms.push_back(static_cast<double>(u->received_ns - u->capture_time_ns) * 1e-6);
    result.seqs.push_back(u->seq);
    const bool new_frames = u->capture_time_ns != frames_ns;
    if (new_frames) {
      in_flight = sent;
      frames_ns = u->capture_time_ns;
      // Moved since the last frames by the command in flight then (odometry() corrects it).
      tracker.at_capture(u->robot,
                         along_arc(Pose2D{}, in_flight.speed_mps, in_flight.turn_rate_rps, period_s)
                             .field_from_robot());
    }
    FollowCommand command;
    const std::optional<Pose2D> pose = tracker.pose();
    // A route planned from a pose: the cameras', or the one this robot reported since they last
    // saw it (not one it reported out of their sight before); else the route it had.
    if (u->robot) told_pose = false;
    if (pose && (u->robot || (told_pose && !u->waypoints_m.empty())) && u->waypoints_m != planned) {
      planned = u->waypoints_m;
      follower.set_path(planned);
    }
    if (pose) {
      // The cameras' obstacles, less one where the robot stands (its own body, seen when its
      // markers were not).
      std::vector<ObstacleDisc> obstacles;
      for (const ObstacleDisc& d : u->obstacles)
        if (!on_robot_body(*pose, d.center_m)) obstacles.push_back(d);
      local.set_obstacles(std::move(obstacles));
      const double now_s =
          sim_clock
              ? result.sim_time_s
              : std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      // The route empties the basket first, and the mouth is over the unload point: it stands
      // until the basket is empty (no stall: it is working).
      const Vec2 mouth = pose->ahead(options.follow.mouth_ahead_m);
      const bool unloading = basket.standing(*u, mouth);
      const int stalls = recovery.stalls();
      const std::optional<FollowCommand> freeing =
          recovery.step(*pose, now_s, balls_left(*u, given_up) > 0 && !unloading);
      if (recovery.stalls() > stalls) {
        if (const std::optional<Vec2> ball = tries.stalled(*u)) {
          const std::string why = "no progress on the way to it after " +
                                  std::to_string(options.give_up_after) + " recoveries";
          if (link.report_unreachable({*ball}, why)) {  // else it is tried again at the next stall
            given_up.push_back(*ball);
            tries.reset();
            ++result.unreachable;
          }
        }
      }
      // Steered from where the robot will be when the command acts.
      const Pose2D acting =
          options.latency_s > 0.0
              ? along_arc(*pose, in_flight.speed_mps, in_flight.turn_rate_rps, options.latency_s)
              : *pose;
      const FollowCommand wanted = unloading ? FollowCommand{}
                                   : freeing ? *freeing
                                             : basket.approach(*u, mouth, follower.command(acting));
      const GuardedCommand guarded =
          local.guard(acting, wanted, follower.carrot(), options.follow.mouth_ahead_m);
      command = guarded.command;
      if (guarded.guard != Guard::as_wanted) ++result.guarded;
    }
    sent = command;
    const std::optional<nlohmann::json> drove =
        link.drive_simulated(u->seq, command.speed_mps, deg_from_rad(command.turn_rate_rps));
    if (drove && drove->contains("time_s")) {
      if (!sim_clock) recovery.restart();  // from now on timed on the court's clock
      const double time_s = drove->value("time_s", result.sim_time_s);
      if (sim_clock && new_frames && time_s > result.sim_time_s) {
        period_s = time_s - result.sim_time_s;
      }
      sim_clock = true;
      result.sim_time_s = time_s;
    }
    if (new_frames && drove) {
      // A reading that is not one is skipped: the prediction stands.
      if (const std::optional<Pose2D> odometry = json_pose_if_any(*drove, "odometry")) {
        tracker.odometry(*odometry);
      }
    }
    // Out of the cameras' sight, the service plans from where the robot says it is.
    if (new_frames && !tracker.seen() && tracker.pose()) {
      told_pose = link.set_pose(*tracker.pose());
      ++result.dead_reckoned;
    }
    const int taken = drove ? drove->value("collected", 0) : 0;
    // The basket: as the court's sensor says, else counted; the service is told until it knows.
    basket.answered(taken, drove && drove->contains("held")
                               ? std::optional<int>(drove->value("held", 0))
                               : std::nullopt);
    if (taken > 0) tries.reset();
    const std::optional<int> tell = basket.to_tell(u->service_id);
    if (taken > 0 && pose) {
      if (link.report_collected(std::vector<Vec2>(static_cast<std::size_t>(taken),
                                                  pose->ahead(options.follow.mouth_ahead_m)),
                                basket.held())) {
        basket.told(basket.held());
      }
      result.collected += taken;
    } else if (tell && link.report_collected({}, *tell)) {
      basket.told(*tell);
    }
    link.acknowledge(u->seq);  // last: the update is dealt with, its collected balls reported
    if (progress && result.updates % 100 == 0) {
      progress("update " + std::to_string(u->seq) + ", " + std::to_string(u->balls_m.size()) +
               " balls seen, " + std::to_string(result.collected) + " collected, simulated time " +
               std::to_string(static_cast<int>(result.sim_time_s)) + " s");
    }
    empty = balls_left(*u, given_up) == 0 && u->visits_m.empty() ? empty + 1 : 0;
    if (empty >= options.done_after) {
      result.done = true;
      break;
    }
  }
  const LinkStatus status = link.status();
  result.stalls = recovery.stalls();
  result.unloads = basket.unloads();
  result.recoveries = recovery.recoveries();
  result.gaps = status.gaps;
  result.reconnects = status.reconnects;
  return result;
}

}  // namespace ballsight
