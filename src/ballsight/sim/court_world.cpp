#include "ballsight/sim/court_world.hpp"

#include <algorithm>
#include <cmath>

namespace ballsight::sim {

CourtWorld::CourtWorld(CourtScene scene, const TennisCourtSpec& court, const DriveLimits& limits,
                       const RobotFootprint& footprint, const RobotImperfections& imperfections,
                       const CollectorBasket& basket)
    : scene_(std::move(scene)),
      court_(court),
      limits_(limits),
      footprint_(footprint),
      imperfections_(imperfections),
      basket_(basket),
      rng_(imperfections.seed) {
  limits_.validate();
  imperfections_.validate();
  motion_.pose = scene_.robot.pose;
  for (const CourtObstacle& o : scene_.obstacles) walk_from_.push_back(o.pose.position);
  walking_out_.assign(scene_.obstacles.size(), true);
}

void CourtWorld::walk_step() {
  for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) {
    CourtObstacle& o = scene_.obstacles[i];
    if (!o.walk_to) continue;
    // It waits for the robot, but not standing on a ball (it steps over balls as it walks).
    const bool on_ball =
        std::any_of(scene_.balls.begin(), scene_.balls.end(), [&](const SceneSphere& b) {
          return (b.center_in_field.head<2>() - o.pose.position).norm() <
                 o.half_size.x() + b.radius_m;
        });
    if (!on_ball && (o.pose.position - motion_.pose.position).norm() < kWalkerWaitM) continue;
    const Vec2 target = walking_out_[i] ? *o.walk_to : walk_from_[i];
    const Vec2 to = target - o.pose.position;
    const double step = o.walk_mps * kStepS;
    if (to.norm() <= step) {
      o.pose.position = target;
      walking_out_[i] = !walking_out_[i];
    } else {
      o.pose.position += step * to.normalized();
    }
  }
}

int CourtWorld::balls_left() const {
  return static_cast<int>(
      std::count_if(scene_.balls.begin(), scene_.balls.end(),
                    [](const SceneSphere& b) { return b.kind == ObjectKind::tennis_ball; }));
}

void CourtWorld::resume(double time_s, const Pose2D& pose, const std::vector<int>& collected,
                        int held) {
  time_s_ = time_s;
  held_ = held;
  standing_s_ = 0.0;
  motion_ = RobotMotion{pose, 0.0, 0.0};
  odometry_ = {};
  pending_.clear();
  acting_ = {};
  scene_.robot.pose = pose;
  remove_balls_if([&](const SceneSphere& b) {
    return std::find(collected.begin(), collected.end(), b.id) != collected.end();
  });
}

bool CourtWorld::unloading_step() {
  const Vec2 mouth = motion_.pose.ahead(footprint_.collector_x_m);
  const bool still = std::abs(motion_.speed_mps) < 0.05 && std::abs(motion_.turn_rate_rps) < 0.1;
  if (basket_.capacity == 0 || held_ == 0 || !still ||
      (mouth - basket_.unload_m).norm() > basket_.reach_m) {
    standing_s_ = 0.0;
    return false;
  }
  standing_s_ += kStepS;
  if (standing_s_ < basket_.unload_s - 1e-9) return false;
  held_ = 0;
  standing_s_ = 0.0;
  return true;
}

const WorldTick& CourtWorld::advance(const DriveCommand& command, double seconds) {
  WorldTick tick;
  const int steps = std::max(1, static_cast<int>(std::lround(seconds / kStepS)));
  pending_.emplace_back(time_s_ + imperfections_.command_latency_s, command);
  // The slip as a first-order Gauss-Markov process: its standard deviation odometry_drift, its
  // correlation time slip_time_s (no random draw for a robot that does not slip).
  const double keep = std::exp(-kStepS / imperfections_.slip_time_s);
  const double kick = imperfections_.odometry_drift * std::sqrt(1.0 - keep * keep);
  std::normal_distribution<double> normal;
  for (int k = 0; k < steps; ++k) {
    const double now = time_s_ + k * kStepS;
    while (!pending_.empty() && pending_.front().first <= now + 1e-9) {
      acting_ = pending_.front().second;
      pending_.pop_front();
    }
    if (kick > 0.0) {
      slip_.speed = keep * slip_.speed + kick * normal(rng_);
      slip_.turn = keep * slip_.turn + kick * normal(rng_);
    }
    walk_step();
    const Pose2D before = motion_.pose;
    const DriveStep step =
        drive_step(motion_, acting_, kStepS, limits_, footprint_, court_, scene_.obstacles, slip_);
    // The wheels turned at the step's mean speeds (a blocked robot's wheels as its motion says).
    odometry_ = along_arc(odometry_, 0.5 * (motion_.speed_mps + step.motion.speed_mps),
                          0.5 * (motion_.turn_rate_rps + step.motion.turn_rate_rps), kStepS);
    motion_ = step.motion;
    tick.blocked = tick.blocked || step.blocked;
    const double clearance =
        footprint_clearance(footprint_, motion_.pose, court_, scene_.obstacles);
    tick.clearance_m =
        std::isnan(tick.clearance_m) ? clearance : std::min(tick.clearance_m, clearance);
    const std::size_t room = basket_.capacity > 0
                                 ? static_cast<std::size_t>(std::max(0, basket_.capacity - held_))
                                 : static_cast<std::size_t>(-1);
    for (int id : collect_swept(scene_, before, motion_.pose, footprint_, room)) {
      tick.collected.push_back(id);
      ++held_;
    }
    if (unloading_step()) tick.unloaded = true;
  }
  tick.held = held_;
  scene_.robot.pose = motion_.pose;
  time_s_ += steps * kStepS;
  tick.time_s = time_s_;
  tick.robot = motion_.pose;
  tick.odometry = odometry_;
  tick.balls_left = balls_left();
  history_.push_back(std::move(tick));
  return history_.back();
}

}  // namespace ballsight::sim
