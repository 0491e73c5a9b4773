#include "ballsight/robot/path_follower.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr double kStraightRad = 0.35;   // 20 degrees: a turn smaller than this is no corner
constexpr double kBackOffM = 0.6;       // a leg this short straight behind is reversed along
constexpr double kFenceBackOffM = 0.8;  // off the fence: from a ball to its lane's edge (0.70 m)
constexpr double kBehindCos = 0.7071;   // "straight behind": within 45 degrees
// A waypoint this far beyond the mouth's circle round the axle is turned to, not crept from.
constexpr double kCreepMarginM = 0.10;
constexpr double kCreepShare = 0.3;  // of full speed, creeping away from a waypoint too near
constexpr double kCreepM = 0.25;     // and this far at most (the waypoint may move with it)
constexpr int kCreepCommands = 12;   // or for this many commands

}  // namespace

void FollowerOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(positive(mouth_ahead_m), "mouth_ahead_m", "must be positive");
  require(positive(lookahead_m), "lookahead_m", "must be positive");
  require(positive(max_speed_mps), "max_speed_mps", "must be positive");
  require(positive(max_turn_rate_rps), "max_turn_rate_rps", "must be positive");
  require(positive(arrive_m), "arrive_m", "must be positive");
  require(positive(slow_down_m), "slow_down_m", "must be positive");
  require(std::isfinite(overshoot_m) && overshoot_m >= 0.0, "overshoot_m", "must not be negative");
}

PathFollower::PathFollower(const FollowerOptions& options) : options_(options) {
  options_.validate();
}

void PathFollower::set_path(std::vector<Vec2> waypoints) {
  path_ = std::move(waypoints);
  if (path_.size() >= 2 && options_.overshoot_m > 0.0) {
    const Vec2 last = path_.back() - path_[path_.size() - 2];
    if (last.norm() > 1e-9) {
      // Along the last leg, ending at the fence at the latest.
      const Vec2 dir = last.normalized();
      double reach = options_.overshoot_m;
      for (int axis = 0; options_.fence && axis < 2; ++axis) {
        if (dir[axis] > 1e-9) {
          reach = std::min(reach, (options_.fence->max_m[axis] - path_.back()[axis]) / dir[axis]);
        } else if (dir[axis] < -1e-9) {
          reach = std::min(reach, (options_.fence->min_m[axis] - path_.back()[axis]) / dir[axis]);
        }
      }
      if (reach > 1e-9) path_.push_back(path_.back() + reach * dir);
    }
  }
  cumulative_.assign(path_.size(), 0.0);
  for (std::size_t i = 1; i < path_.size(); ++i) {
    cumulative_[i] = cumulative_[i - 1] + (path_[i] - path_[i - 1]).norm();
  }
  progress_ = 0.0;
}

Vec2 PathFollower::at(double s) const {
  if (s <= 0.0) return path_.front();
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  if (it == cumulative_.end()) return path_.back();
  const std::size_t i = static_cast<std::size_t>(it - cumulative_.begin());
  const double leg = cumulative_[i] - cumulative_[i - 1];
  const double t = leg > 0.0 ? (s - cumulative_[i - 1]) / leg : 1.0;
  return path_[i - 1] + t * (path_[i] - path_[i - 1]);
}

FollowCommand PathFollower::command(const Pose2D& pose) {
  const Vec2 h(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
  const Vec2 h_perp(-h.y(), h.x());
  const Vec2 mouth = pose.position + options_.mouth_ahead_m * h;
  carrot_ = path_.empty() ? mouth : path_.back();
  if (path_.empty()) return {0.0, 0.0, true};
  // Progress: the closest point of the path to the mouth, searched a little ahead of the last
  // progress only (the path may cross itself; progress never goes back).
  const double total = cumulative_.back();
  double best = progress_, best_d = (at(progress_) - mouth).norm();
  for (double s = progress_; s <= std::min(total, progress_ + 2.0); s += 0.02) {
    const double d = (at(s) - mouth).norm();
    if (d < best_d) {
      best_d = d;
      best = s;
    }
  }
  progress_ = best;
  const double to_end = (path_.back() - mouth).norm();
  if (total - progress_ < options_.arrive_m + 1e-9 && to_end < options_.arrive_m) {
    return {0.0, 0.0, true};
  }
  // The next corner beyond the mouth's progress: a waypoint where the path turns (once the mouth
  // is within arrive_m of one, the next).
  double corner = total;
  for (auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), progress_);
       it + 1 < cumulative_.end(); ++it) {
    const std::size_t i = static_cast<std::size_t>(it - cumulative_.begin());
    if ((path_[i] - mouth).norm() < options_.arrive_m) continue;
    const Vec2 in = path_[i] - path_[i - 1], out = path_[i + 1] - path_[i];
    if (in.norm() > 1e-9 && out.norm() > 1e-9 &&
        in.dot(out) > std::cos(kStraightRad) * in.norm() * out.norm()) {
      continue;  // (nearly) straight on: no corner
    }
    corner = cumulative_[i];
    break;
  }
  carrot_ = at(std::min(progress_ + options_.lookahead_m, corner));
  const Vec2 towards = carrot_ - mouth;
  const double distance = towards.norm();
  if (distance < 1e-9) return {0.0, 0.0, true};
  // Slow for the waypoint ahead when the path turns there, and for the end.
  const double remaining = corner >= total ? std::max(total - progress_, to_end)
                                           : std::max(corner - progress_, 0.0) + 0.2;
  const double speed =
      options_.max_speed_mps * std::clamp(remaining / options_.slow_down_m, 0.15, 1.0);
  const Vec2 u = speed * towards / distance;
  // A short leg straight behind (backing off the net after a ball against it, where the body has
  // no room to turn): reversed along, the same linearisation steering the mouth.
  const bool at_fence = options_.inside_fence_lane && !options_.inside_fence_lane->contains(mouth);
  const bool in_zone =
      at_fence || (options_.back_off_zone && options_.back_off_zone->contains(mouth));
  const bool back_off = in_zone && u.dot(h) < -kBehindCos * speed &&
                        corner - progress_ < (at_fence ? kFenceBackOffM : kBackOffM);
  // Off the fence straight back, as the robot came in: steering the mouth while reversing swings
  // the body's corners into the fence.
  if (back_off && at_fence) return {u.dot(h), 0.0, false};
  if (u.dot(h) < 0.0 && !back_off) {  // the carrot is behind: turn on the spot towards it (the
                                      // mouth collects only driving forwards), the way the turn
                                      // began (a carrot straight behind must not flip it)
    // A waypoint within the mouth's circle round the axle (a ball beside the body) is never
    // reached by turning: creep forward first, away from it, then turn; not in the back-off
    // zone (the net is ahead there), and for a few commands at most (something may be in the
    // way, or the waypoint move with the robot).
    if (!in_zone && (at(corner) - pose.position).norm() < options_.mouth_ahead_m + kCreepMarginM &&
        (!creep_from_ ||
         ((pose.position - *creep_from_).norm() < kCreepM && creep_commands_ < kCreepCommands))) {
      if (!creep_from_) {
        creep_from_ = pose.position;
        creep_commands_ = 0;
      }
      ++creep_commands_;
      spin_ = 0.0;
      return {kCreepShare * options_.max_speed_mps, 0.0, false};
    }
    if (spin_ == 0.0) spin_ = u.dot(h_perp) < 0.0 ? -1.0 : 1.0;
    return {0.0, spin_ * options_.max_turn_rate_rps, false};
  }
  spin_ = 0.0;
  creep_from_.reset();
  double v = u.dot(h);
  double w = u.dot(h_perp) / options_.mouth_ahead_m;
  // Within the turn rate: scale the whole velocity, so that the mouth keeps its direction.
  if (std::abs(w) > options_.max_turn_rate_rps) {
    const double k = options_.max_turn_rate_rps / std::abs(w);
    v *= k;
    w *= k;
  }
  return {v, w, false};
}

}  // namespace ballsight
