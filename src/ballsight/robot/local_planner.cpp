#include "ballsight/robot/local_planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr double kStepS = 0.05;         // the imagined drive's time step
constexpr double kScoreHorizonS = 2.0;  // a replacement is scored where it leads in this time
constexpr double kFacingWeightM = 0.3;  // metres of mouth distance worth a radian of facing
constexpr double kNoNearerM = 0.002;    // an outline inside the margin: "no nearer" tolerance
constexpr double kBetterM = 0.01;       // a replacement must beat standing by this much
constexpr int kKeepPeriods = 5;  // a replacement is kept this many periods while it keeps clear
constexpr std::array<double, 3> kSlower{0.75, 0.5, 0.25};
// Of the top speed and turn rate: back, stand, creep and drive on; turning hard, gently (an arc of
// metres: the way out alongside the net, where a turn on the spot swings a corner into it) and not.
constexpr std::array<double, 5> kSpeedShares{-0.3, -0.15, 0.0, 0.15, 0.3};
constexpr std::array<double, 7> kTurnShares{-0.5, -0.15, -0.05, 0.0, 0.05, 0.15, 0.5};

double towards(double value, double step) {
  return value > 0.0 ? std::max(0.0, value - step) : std::min(0.0, value + step);
}

}  // namespace

void LocalPlannerOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(body.back_m + body.front_m) && positive(body.half_width_m), "body",
          "must have a positive length and width");
  require(std::isfinite(margin_m) && margin_m >= 0.0, "margin_m", "must not be negative");
  require(std::isfinite(contact_m) && contact_m >= 0.0 && contact_m <= margin_m, "contact_m",
          "must be in [0, margin_m]");
  require(positive(period_s), "period_s", "must be positive");
  require(positive(max_accel_mps2), "max_accel_mps2", "must be positive");
  require(positive(max_turn_accel_rps2), "max_turn_accel_rps2", "must be positive");
  require(positive(max_speed_mps), "max_speed_mps", "must be positive");
  require(positive(max_turn_rate_rps), "max_turn_rate_rps", "must be positive");
}

LocalPlanner::LocalPlanner(Costmap costmap, const LocalPlannerOptions& options)
    : costmap_(std::move(costmap)), options_(options) {
  options_.validate();
}

double LocalPlanner::clearance(const Pose2D& pose) const {
  const BodyOutline& b = options_.body;
  const Rigid2 field_from_robot = pose.field_from_robot();
  const std::array<Vec2, 4> corners{
      Vec2(b.front_m, b.half_width_m), Vec2(-b.back_m, b.half_width_m),
      Vec2(-b.back_m, -b.half_width_m), Vec2(b.front_m, -b.half_width_m)};
  double nearest = INFINITY;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2& from = corners[i];
    const Vec2& to = corners[(i + 1) % corners.size()];
    const int steps =
        std::max(1, static_cast<int>(std::ceil((to - from).norm() / costmap_.resolution_m())));
    for (int k = 0; k < steps; ++k) {
      const Vec2 p = from + (to - from) * (static_cast<double>(k) / steps);
      nearest = std::min(nearest, costmap_.clearance(field_from_robot * p));
    }
  }
  return nearest;
}

bool LocalPlanner::clear(const Pose2D& pose, const FollowCommand& command, double start_clearance,
                         double limit_m) const {
  const double least = std::min(limit_m, start_clearance - kNoNearerM);
  double v = command.speed_mps, w = command.turn_rate_rps;
  Pose2D at = pose;
  for (double t = kStepS; std::abs(v) > 1e-9 || std::abs(w) > 1e-9; t += kStepS) {
    at = along_arc(at, v, w, kStepS);
    if (clearance(at) < least) return false;
    if (t >= options_.period_s - 1e-9) {  // braking
      v = towards(v, options_.max_accel_mps2 * kStepS);
      w = towards(w, options_.max_turn_accel_rps2 * kStepS);
    }
  }
  return true;
}

GuardedCommand LocalPlanner::guard(const Pose2D& pose, const FollowCommand& wanted,
                                   const Vec2& carrot, double mouth_ahead_m) {
  const double start = clearance(pose);
  if (clear(pose, wanted, start, options_.margin_m)) {
    kept_.reset();
    return {wanted, Guard::as_wanted};
  }
  for (const double share : kSlower) {
    const FollowCommand slower{share * wanted.speed_mps, share * wanted.turn_rate_rps, false};
    if (clear(pose, slower, start, options_.margin_m)) {
      kept_.reset();
      return {slower, Guard::slowed};
    }
  }
  // Where each command leads in a few seconds: the mouth's distance to the carrot and how far
  // the heading is from facing it; failing that, the body's distance from the obstacles.
  // (A command is followed only as far as it keeps clear: beyond, it would be replaced.)
  const double least = std::min(options_.contact_m, start - kNoNearerM);
  const auto end_of = [&](const FollowCommand& c) {
    Pose2D end = pose;
    for (double t = kStepS; t <= kScoreHorizonS + 1e-9; t += kStepS) {
      const Pose2D next = along_arc(end, c.speed_mps, c.turn_rate_rps, kStepS);
      if (clearance(next) < least) break;
      end = next;
    }
    return end;
  };
  const auto score = [&](const Pose2D& end) {
    const Vec2 h(std::cos(end.heading_rad), std::sin(end.heading_rad));
    const Vec2 to_carrot = carrot - (end.position + mouth_ahead_m * h);
    const double facing =
        to_carrot.norm() > 1e-9
            ? std::abs(wrap_rad_pi(std::atan2(to_carrot.y(), to_carrot.x()) - end.heading_rad))
            : 0.0;
    return to_carrot.norm() + kFacingWeightM * facing;
  };
  // A replacement under way is kept for a few periods while it keeps clear (after DWB's
  // oscillation critic: flipping between driving on and backing every period goes nowhere).
  if (kept_ && kept_periods_ < kKeepPeriods && clear(pose, *kept_, start, options_.contact_m)) {
    ++kept_periods_;
    return {*kept_, Guard::replaced};
  }
  kept_.reset();
  std::optional<FollowCommand> nearer, away;
  double best_score = score(pose) - kBetterM, best_room = start + kBetterM;
  for (const double v : kSpeedShares) {
    for (const double w : kTurnShares) {
      const FollowCommand c{v * options_.max_speed_mps, w * options_.max_turn_rate_rps, false};
      if ((v == 0.0 && w == 0.0) || !clear(pose, c, start, options_.contact_m)) continue;
      const Pose2D end = end_of(c);
      if (const double s = score(end); s < best_score) {
        nearer = c;
        best_score = s;
      }
      if (const double room = clearance(end); room > best_room) {
        away = c;
        best_room = room;
      }
    }
  }
  if (!nearer && !away) return {FollowCommand{}, Guard::stopped};
  kept_ = nearer ? *nearer : *away;
  kept_periods_ = 1;
  return {*kept_, Guard::replaced};
}

}  // namespace ballsight
