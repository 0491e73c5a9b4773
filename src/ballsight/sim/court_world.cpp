#include "ballsight/sim/court_world.hpp"

#include <algorithm>
#include <cmath>

namespace ballsight::sim {

CourtWorld::CourtWorld(CourtScene scene, const TennisCourtSpec& court, const DriveLimits& limits,
                       const RobotFootprint& footprint)
    : scene_(std::move(scene)), court_(court), limits_(limits), footprint_(footprint) {
  limits_.validate();
  motion_.pose = scene_.robot.pose;
}

int CourtWorld::balls_left() const {
  return static_cast<int>(
      std::count_if(scene_.balls.begin(), scene_.balls.end(),
                    [](const SceneSphere& b) { return b.kind == ObjectKind::tennis_ball; }));
}

void CourtWorld::resume(double time_s, const Pose2D& pose, const std::vector<int>& collected) {
  time_s_ = time_s;
  motion_ = RobotMotion{pose, 0.0, 0.0};
  scene_.robot.pose = pose;
  remove_balls_if([&](const SceneSphere& b) {
    return std::find(collected.begin(), collected.end(), b.id) != collected.end();
  });
}

const WorldTick& CourtWorld::advance(const DriveCommand& command, double seconds) {
  WorldTick tick;
  const int steps = std::max(1, static_cast<int>(std::lround(seconds / kStepS)));
  for (int k = 0; k < steps; ++k) {
    const Pose2D before = motion_.pose;
    const DriveStep step = drive_step(motion_, command, kStepS, limits_, footprint_, court_);
    motion_ = step.motion;
    tick.blocked = tick.blocked || step.blocked;
    for (int id : collect_swept(scene_, before, motion_.pose, footprint_)) {
      tick.collected.push_back(id);
    }
  }
  scene_.robot.pose = motion_.pose;
  time_s_ += steps * kStepS;
  tick.time_s = time_s_;
  tick.robot = motion_.pose;
  tick.balls_left = balls_left();
  history_.push_back(std::move(tick));
  return history_.back();
}

}  // namespace ballsight::sim
