#include "ballsight/plan/obstacle_detours.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/segment_distance.hpp"

namespace ballsight {
namespace {

constexpr int kSides = 8;              // of the polygon round each obstacle
constexpr double kCornerRoomM = 0.02;  // the polygon's sides pass this far outside the keep-out
constexpr double kTouchM = 1e-6;       // a path on the keep-out's edge is clear
constexpr std::size_t kMaxDiscs = 16;

DrivablePath reversed(DrivablePath path) {
  std::reverse(path.via.begin(), path.via.end());
  return path;
}

}  // namespace

ObstacleDetours::ObstacleDetours(const DrivableCourt& court, std::vector<ObstacleDisc> discs,
                                 double keep_m)
    : discs_(std::move(discs)), keep_m_(keep_m) {
  require(std::isfinite(keep_m) && keep_m >= 0.0 && keep_m <= 2.0, "obstacle keep_m",
          "must be in [0, 2] m");
  require(discs_.size() <= kMaxDiscs, "obstacles",
          "at most " + std::to_string(kMaxDiscs) + ", got " + std::to_string(discs_.size()));
  for (std::size_t i = 0; i < discs_.size(); ++i) {
    require(discs_[i].center_m.allFinite() && std::isfinite(discs_[i].radius_m) &&
                discs_[i].radius_m >= 0.0 && discs_[i].radius_m <= 5.0,
            "obstacles[" + std::to_string(i) + "]", "centre must be finite, radius in [0, 5] m");
  }
  DrivableCourt bare = court;
  bare.obstacles.reset();
  for (const ObstacleDisc& d : discs_) {
    const double reach = (d.radius_m + keep_m_ + kCornerRoomM) / std::cos(kPi / kSides);
    for (int k = 0; k < kSides; ++k) {
      const double angle = (2.0 * k + 1.0) * kPi / kSides;
      const Vec2 corner = d.center_m + reach * Vec2(std::cos(angle), std::sin(angle));
      if (!bare.in_area(corner) || bare.in_net_lane(corner) || bare.in_fence_lane(corner) ||
          exit_of(corner) != corner) {
        continue;
      }
      corners_.push_back(corner);
    }
  }
  const std::size_t n = corners_.size();
  distance_.assign(n * n, INFINITY);
  next_.assign(n * n, -1);
  legs_.resize(n * n);
  for (std::size_t u = 0; u < n; ++u) {
    distance_[u * n + u] = 0.0;
    next_[u * n + u] = static_cast<int>(u);
    for (std::size_t v = u + 1; v < n; ++v) {
      DrivablePath leg = net_path(bare, corners_[u], corners_[v]);
      if (!clear(corners_[u], leg, corners_[v])) continue;
      distance_[u * n + v] = distance_[v * n + u] = leg.length_m;
      next_[u * n + v] = static_cast<int>(v);
      next_[v * n + u] = static_cast<int>(u);
      legs_[v * n + u] = reversed(leg);
      legs_[u * n + v] = std::move(leg);
    }
  }
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (distance_[i * n + k] + distance_[k * n + j] < distance_[i * n + j]) {
          distance_[i * n + j] = distance_[i * n + k] + distance_[k * n + j];
          next_[i * n + j] = next_[i * n + k];
        }
}

Vec2 ObstacleDetours::exit_of(const Vec2& p) const {
  // Out of each keep-out in turn (out of one may be into another where two overlap): a few
  // rounds, then where it got.
  Vec2 at = p;
  for (int round = 0; round < 4; ++round) {
    bool moved = false;
    for (const ObstacleDisc& d : discs_) {
      const Vec2 out = at - d.center_m;
      const double keep = d.radius_m + keep_m_;
      if (out.norm() >= keep - kTouchM) continue;
      const Vec2 away = out.norm() > 1e-9 ? Vec2(out.normalized()) : Vec2::UnitX();
      at = d.center_m + keep * away;
      moved = true;
    }
    if (!moved) break;
  }
  return at;
}

bool ObstacleDetours::clear(const Vec2& a, const DrivablePath& path, const Vec2& b) const {
  Vec2 from = a;
  for (std::size_t k = 0; k <= path.via.size(); ++k) {
    const Vec2& to = k < path.via.size() ? path.via[k] : b;
    for (const ObstacleDisc& d : discs_)
      if (segment_distance(d.center_m, from, to) < d.radius_m + keep_m_ - kTouchM) return false;
    from = to;
  }
  return true;
}

DrivablePath ObstacleDetours::route(const DrivableCourt& court, const Vec2& a,
                                    const Vec2& b) const {
  DrivablePath direct = net_path(court, a, b);
  if (clear(a, direct, b)) return direct;
  // Out of a keep-out straight, round the obstacles, into one straight.
  const Vec2 a_out = exit_of(a), b_out = exit_of(b);
  DrivablePath inner = net_path(court, a_out, b_out);
  if (!clear(a_out, inner, b_out)) {
    const std::size_t n = corners_.size();
    std::vector<DrivablePath> from_a(n), to_b(n);
    std::vector<bool> a_sees(n), b_sees(n);
    for (std::size_t u = 0; u < n; ++u) {
      from_a[u] = net_path(court, a_out, corners_[u]);
      a_sees[u] = clear(a_out, from_a[u], corners_[u]);
      to_b[u] = net_path(court, corners_[u], b_out);
      b_sees[u] = clear(corners_[u], to_b[u], b_out);
    }
    double best = INFINITY;
    std::size_t first = 0, last = 0;
    for (std::size_t u = 0; u < n; ++u) {
      if (!a_sees[u]) continue;
      for (std::size_t w = 0; w < n; ++w) {
        if (!b_sees[w]) continue;
        const double length = from_a[u].length_m + distance_[u * n + w] + to_b[w].length_m;
        if (length < best) {
          best = length;
          first = u;
          last = w;
        }
      }
    }
    if (best == INFINITY) return direct;  // no way round: the robot's local planner stops short
    inner = from_a[first];
    inner.length_m = best;
    for (std::size_t u = first; u != last;) {
      const auto v = static_cast<std::size_t>(next_[u * n + last]);
      inner.via.push_back(corners_[u]);
      const DrivablePath& leg = legs_[u * n + v];
      inner.via.insert(inner.via.end(), leg.via.begin(), leg.via.end());
      u = v;
    }
    inner.via.push_back(corners_[last]);
    inner.via.insert(inner.via.end(), to_b[last].via.begin(), to_b[last].via.end());
  }
  DrivablePath path;
  if (a_out != a) path.via.push_back(a_out);
  path.via.insert(path.via.end(), inner.via.begin(), inner.via.end());
  if (b_out != b) path.via.push_back(b_out);
  path.length_m = (a_out - a).norm() + inner.length_m + (b - b_out).norm();
  return path;
}

bool on_robot_body(const Pose2D& pose, const Vec2& p) {
  constexpr double kHalfLengthM = 0.40, kHalfWidthM = 0.45;
  const Vec2 local = pose.field_from_robot().inverse() * p;
  return std::abs(local.x()) <= kHalfLengthM && std::abs(local.y()) <= kHalfWidthM;
}

DrivableCourt with_obstacles(DrivableCourt court, std::vector<ObstacleDisc> discs, double keep_m) {
  if (discs.empty()) {
    court.obstacles.reset();
    return court;
  }
  court.obstacles = std::make_shared<const ObstacleDetours>(court, std::move(discs), keep_m);
  return court;
}

}  // namespace ballsight
