#include "ballsight/sim/robot_motion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/segment_distance.hpp"

namespace ballsight::sim {
namespace {

/// `value` moved towards `target` by at most `step`.
double approach(double value, double target, double step) {
  return value + std::clamp(target - value, -step, step);
}

/// A rectangle as its four corners, counter-clockwise.
using Corners = std::array<Vec2, 4>;

Corners footprint_corners(const RobotFootprint& f, const Pose2D& pose) {
  const Vec2 forward(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
  const Vec2 left(-forward.y(), forward.x());
  const auto at = [&](double x, double y) -> Vec2 {
    return pose.position + x * forward + y * left;
  };
  return {at(-f.back_m, -f.half_width_m), at(f.front_m, -f.half_width_m),
          at(f.front_m, f.half_width_m), at(-f.back_m, f.half_width_m)};
}

/// Whether two convex quadrilaterals overlap (separating axis theorem over their edges).
bool overlap(const Corners& a, const Corners& b) {
  for (const Corners* shape : {&a, &b}) {
    for (int i = 0; i < 4; ++i) {
      const Vec2 edge = (*shape)[(i + 1) % 4] - (*shape)[i];
      const Vec2 axis(-edge.y(), edge.x());
      double a_min = 1e300, a_max = -1e300, b_min = 1e300, b_max = -1e300;
      for (const Vec2& p : a) {
        a_min = std::min(a_min, axis.dot(p));
        a_max = std::max(a_max, axis.dot(p));
      }
      for (const Vec2& p : b) {
        b_min = std::min(b_min, axis.dot(p));
        b_max = std::max(b_max, axis.dot(p));
      }
      if (a_max < b_min || b_max < a_min) return false;
    }
  }
  return true;
}

/// Distance between two convex quadrilaterals that do not overlap: the nearest pair of a corner
/// of one and an edge of the other.
double gap(const Corners& a, const Corners& b) {
  double nearest = INFINITY;
  for (const auto& [points, edges] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    for (const Vec2& p : *points) {
      for (int i = 0; i < 4; ++i) {
        nearest = std::min(nearest, segment_distance(p, (*edges)[i], (*edges)[(i + 1) % 4]));
      }
    }
  }
  return nearest;
}

/// The net as the referee has it: the mesh on x = 0 between the post centres, as thick as the
/// posts.
Corners net_corners(const TennisCourtSpec& court) {
  const double half_span =
      court.doubles_width_m / 2.0 + court.net.post_outside_doubles_m + court.net.post_radius_m;
  const double half_depth = court.net.post_radius_m;
  return {Vec2(-half_depth, -half_span), Vec2(half_depth, -half_span), Vec2(half_depth, half_span),
          Vec2(-half_depth, half_span)};
}

/// Whether `p` lies inside the convex quadrilateral `q` (counter-clockwise).
bool inside(const Corners& q, const Vec2& p) {
  for (int i = 0; i < 4; ++i) {
    const Vec2 edge = q[(i + 1) % 4] - q[i], to = p - q[i];
    if (edge.x() * to.y() - edge.y() * to.x() < 0.0) return false;
  }
  return true;
}

/// The gap between the robot's body and `obstacle`'s footprint; 0 where they overlap.
double obstacle_gap(const Corners& body, const CourtObstacle& obstacle) {
  if (obstacle.kind == ObstacleKind::person) {
    const Vec2& c = obstacle.pose.position;
    if (inside(body, c)) return 0.0;
    double nearest = INFINITY;
    for (int i = 0; i < 4; ++i)
      nearest = std::min(nearest, segment_distance(c, body[i], body[(i + 1) % 4]));
    return std::max(0.0, nearest - obstacle.half_size.x());
  }
  const FloorBox box = obstacle.bounds();
  const Corners bag = footprint_corners(
      RobotFootprint{box.half_size.x(), box.half_size.x(), box.half_size.y(), 0.0, 0.0}, box.pose);
  return overlap(body, bag) ? 0.0 : gap(body, bag);
}

}  // namespace

void DriveLimits::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(max_speed_mps), "robot.max_speed_mps", "must be positive");
  require(positive(max_accel_mps2), "robot.max_accel_mps2", "must be positive");
  require(positive(max_turn_rate_dps), "robot.turn_rate_dps", "must be positive");
  require(positive(max_turn_accel_dps2), "robot.turn_accel_dps2", "must be positive");
}

RobotFootprint RobotFootprint::of(const RobotBox& box, double collector_x_m,
                                  double collector_width_m) {
  RobotFootprint f;
  f.back_m = box.length_m / 2.0;
  f.front_m = std::max(box.length_m / 2.0, collector_x_m);
  f.half_width_m = std::max(box.width_m, collector_width_m) / 2.0;
  f.collector_x_m = collector_x_m;
  f.collector_width_m = collector_width_m;
  return f;
}

bool footprint_blocked(const RobotFootprint& footprint, const Pose2D& pose,
                       const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles) {
  const Corners corners = footprint_corners(footprint, pose);
  for (const Vec2& c : corners) {
    if (std::abs(c.x()) > court.surround_length_m / 2.0 ||
        std::abs(c.y()) > court.surround_width_m / 2.0) {
      return true;
    }
  }
  for (const CourtObstacle& o : obstacles)
    if (obstacle_gap(corners, o) <= 0.0) return true;
  return court.net.enabled && overlap(corners, net_corners(court));
}

double footprint_clearance(const RobotFootprint& footprint, const Pose2D& pose,
                           const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles) {
  const Corners corners = footprint_corners(footprint, pose);
  // Inside the fence's rectangle the nearest point of the body to it is a corner (negative: one
  // beyond it, as footprint_blocked has it).
  double nearest = INFINITY;
  for (const Vec2& c : corners) {
    nearest = std::min({nearest, court.surround_length_m / 2.0 - std::abs(c.x()),
                        court.surround_width_m / 2.0 - std::abs(c.y())});
  }
  if (nearest < 0.0) return 0.0;
  for (const CourtObstacle& o : obstacles) nearest = std::min(nearest, obstacle_gap(corners, o));
  if (!court.net.enabled) return nearest;
  const Corners net = net_corners(court);
  return overlap(corners, net) ? 0.0 : std::min(nearest, gap(corners, net));
}

void RobotImperfections::validate() const {
  require(std::isfinite(command_latency_s) && command_latency_s >= 0.0 && command_latency_s <= 5.0,
          "command_latency_s", "must be in [0, 5] s");
  require(std::isfinite(odometry_drift) && odometry_drift >= 0.0 && odometry_drift <= 0.5,
          "odometry_drift", "must be in [0, 0.5]");
  require(std::isfinite(slip_time_s) && slip_time_s > 0.0, "slip_time_s", "must be positive");
}

DriveStep drive_step(const RobotMotion& motion, const DriveCommand& command, double dt,
                     const DriveLimits& limits, const RobotFootprint& footprint,
                     const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles,
                     const Slip& slip) {
  const double max_turn = rad_from_deg(limits.max_turn_rate_dps);
  const double v_target =
      std::clamp(command.speed_mps, -limits.max_speed_mps, limits.max_speed_mps);
  const double w_target = std::clamp(command.turn_rate_rps, -max_turn, max_turn);
  RobotMotion next = motion;
  next.speed_mps = approach(motion.speed_mps, v_target, limits.max_accel_mps2 * dt);
  next.turn_rate_rps =
      approach(motion.turn_rate_rps, w_target, rad_from_deg(limits.max_turn_accel_dps2) * dt);
  // The arc at the step's mean speeds, less the slip.
  const double v = 0.5 * (motion.speed_mps + next.speed_mps) * (1.0 - slip.speed);
  const double w = 0.5 * (motion.turn_rate_rps + next.turn_rate_rps) * (1.0 - slip.turn);
  next.pose = along_arc(motion.pose, v, w, dt);
  if (!footprint_blocked(footprint, next.pose, court, obstacles)) return {next, false};
  // In contact: the part of the motion the obstacle allows (sliding straight on, or turning on
  // the spot), else none.
  RobotMotion slide = motion;
  slide.turn_rate_rps = 0.0;
  slide.speed_mps = next.speed_mps;
  slide.pose.position = along_arc(motion.pose, v, 0.0, dt).position;
  if (std::abs(v) > 1e-9 && !footprint_blocked(footprint, slide.pose, court, obstacles))
    return {slide, true};
  RobotMotion turn = motion;
  turn.speed_mps = 0.0;
  turn.turn_rate_rps = next.turn_rate_rps;
  turn.pose = along_arc(motion.pose, 0.0, w, dt);
  if (std::abs(w * dt) > 1e-12 && !footprint_blocked(footprint, turn.pose, court, obstacles)) {
    return {turn, true};
  }
  RobotMotion stopped = motion;
  stopped.speed_mps = 0.0;
  stopped.turn_rate_rps = 0.0;
  return {stopped, true};
}

bool mouth_can_reach(const RobotFootprint& footprint, const Vec2& ball, double ball_radius_m,
                     const TennisCourtSpec& court, std::span<const CourtObstacle> obstacles) {
  const double across = std::max(0.0, footprint.collector_width_m / 2.0 - ball_radius_m);
  for (int deg = 0; deg < 360; deg += 5) {
    const double heading = rad_from_deg(deg);
    const Vec2 ahead(std::cos(heading), std::sin(heading)), left(-ahead.y(), ahead.x());
    for (double s = -across; s <= across + 1e-9; s += 0.02) {
      const Pose2D pose{ball - footprint.collector_x_m * ahead - s * left, heading};
      if (!footprint_blocked(footprint, pose, court, obstacles)) return true;
    }
  }
  return false;
}

std::vector<int> collect_swept(CourtScene& scene, const Pose2D& before, const Pose2D& after,
                               const RobotFootprint& footprint, std::size_t room) {
  // The ball's place in the robot's frame: ahead of the mouth before, at or behind it after.
  const auto local = [](const Pose2D& pose, const Vec2& p) {
    const Vec2 d = p - pose.position;
    const double c = std::cos(pose.heading_rad), s = std::sin(pose.heading_rad);
    return Vec2(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  };
  const double half = footprint.collector_width_m / 2.0;
  std::vector<int> ids;
  std::erase_if(scene.balls, [&](const SceneSphere& ball) {
    if (ball.kind != ObjectKind::tennis_ball) return false;
    const Vec2 p = ball.center_in_field.head<2>();
    const Vec2 a = local(before, p), b = local(after, p);
    const double grab = footprint.collector_x_m + ball.radius_m;  // the mouth touches the ball
    const bool crossed = a.x() > grab && b.x() <= grab;
    const bool inside = b.x() <= grab && b.x() <= a.x() && b.x() > -footprint.back_m &&
                        std::abs(b.y()) <= half;  // e.g. turned onto it on the spot
    const bool taken = ids.size() < room &&
                       ((crossed && std::abs(a.y()) <= half + 0.05 && std::abs(b.y()) <= half) ||
                        (inside && a.x() > footprint.collector_x_m - 0.05));
    if (taken) ids.push_back(ball.id);
    return taken;
  });
  return ids;
}

}  // namespace ballsight::sim
