#include "ballsight/plan/drivable_court.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr double kEps = 1e-9;

bool lexicographic_less(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

double side_of(const Vec2& p) {
  return p.x() >= 0.0 ? 1.0 : -1.0;
}

/// The open segment a-b passes through the open rectangle |x| < half.x, |y| < half.y.
bool crosses(const Vec2& half, const Vec2& a, const Vec2& b) {
  // Both ends on one side of it: clear (most pairs of a court; no clipping needed).
  for (int axis = 0; axis < 2; ++axis) {
    if ((a[axis] >= half[axis] && b[axis] >= half[axis]) ||
        (a[axis] <= -half[axis] && b[axis] <= -half[axis])) {
      return false;
    }
  }
  // Liang-Barsky clip of the segment against the rectangle.
  const Vec2 d = b - a;
  double t_in = 0.0, t_out = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-15) {
      if (std::abs(a[axis]) >= half[axis] - kEps) return false;
      continue;
    }
    double t0 = (-half[axis] - a[axis]) / d[axis];
    double t1 = (half[axis] - a[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_in = std::max(t_in, t0);
    t_out = std::min(t_out, t1);
  }
  return (t_out - t_in) * d.norm() > kEps;
}

/// Where a path from `p` inside the lane leaves it: straight away from the net.
Vec2 lane_exit(const DrivableCourt& court, const Vec2& p) {
  if (!court.in_net_lane(p)) return p;
  return {side_of(p) * court.net->travel_clearance_m, p.y()};
}

/// Shortest path with a before b in lexicographic order, so that a path and its reverse bend at
/// the same points: out of the lane straight from a, Dijkstra over that exit, the lane's four
/// corners and b's exit, joined where the segment between them is clear (the shortest path round
/// a convex obstacle bends only at its corners), and into the lane straight to b.
DrivablePath canonical_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  DrivablePath best;
  best.length_m = (b - a).norm();
  if (!court.blocked(a, b)) return best;
  const double c = court.net->travel_clearance_m;
  const double y_end = court.net->end_m();
  const Vec2 a_exit = lane_exit(court, a), b_exit = lane_exit(court, b);
  const std::array<Vec2, 6> node{a_exit,           Vec2(c, y_end),  Vec2(-c, y_end),
                                 Vec2(-c, -y_end), Vec2(c, -y_end), b_exit};
  constexpr std::size_t kB = 5;
  std::array<double, 6> dist;
  dist.fill(INFINITY);
  std::array<int, 6> prev;
  prev.fill(-1);
  std::array<bool, 6> done{};
  dist[0] = 0.0;
  for (std::size_t round = 0; round < node.size(); ++round) {
    std::size_t u = node.size();
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (!done[i] && (u == node.size() || dist[i] < dist[u])) u = i;
    }
    if (u == node.size() || dist[u] == INFINITY || u == kB) break;
    done[u] = true;
    for (std::size_t v = 0; v < node.size(); ++v) {
      if (done[v] || court.blocked(node[u], node[v])) continue;
      const double d = dist[u] + (node[v] - node[u]).norm();
      if (d < dist[v] - kEps) {
        dist[v] = d;
        prev[v] = static_cast<int>(u);
      }
    }
  }
  // Inside a convex fence round a rectangle there is always a way; assert it was found.
  assert(dist[kB] < INFINITY);
  best.length_m = (a_exit - a).norm() + dist[kB] + (b - b_exit).norm();
  std::array<Vec2, 4> corners{};
  int count = 0;
  for (int v = prev[kB]; v > 0; v = prev[static_cast<std::size_t>(v)]) {
    corners[static_cast<std::size_t>(count++)] = node[static_cast<std::size_t>(v)];
  }
  const auto add = [&best](const Vec2& p) {
    assert(best.via_count < static_cast<int>(best.via.size()));  // two exits, two corners
    best.via[static_cast<std::size_t>(best.via_count++)] = p;
  };
  if (a_exit != a) add(a_exit);
  for (int i = count - 1; i >= 0; --i) add(corners[static_cast<std::size_t>(i)]);
  if (b_exit != b) add(b_exit);
  return best;
}

}  // namespace

void DrivableCourt::validate() const {
  require(area_min_m.allFinite() && area_max_m.allFinite(), "drivable area", "must be finite");
  require(area_min_m.x() < area_max_m.x() && area_min_m.y() < area_max_m.y(), "drivable area",
          "its minimum corner must lie below and left of its maximum corner");
  if (!net) return;
  require(net->half_length_m > 0.0, "net.half_length_m", "must be positive");
  require(net->clearance_m >= 0.0, "net.clearance_m", "must not be negative");
  require(net->post_clearance_m >= 0.0, "net.post_clearance_m", "must not be negative");
  require(net->travel_clearance_m >= net->clearance_m, "net.travel_clearance_m",
          "must not be less than net.clearance_m (the lane holds the reach keep-out)");
  const double y_end = net->end_m();
  require(area_min_m.x() < -net->travel_clearance_m && area_max_m.x() > net->travel_clearance_m &&
              area_min_m.y() < -y_end && area_max_m.y() > y_end,
          "drivable area",
          "must contain the net's keep-out with room to drive round both posts (" +
              std::to_string(y_end) + " m from the centre line)");
}

bool DrivableCourt::in_area(const Vec2& p) const {
  return p.x() >= area_min_m.x() && p.x() <= area_max_m.x() && p.y() >= area_min_m.y() &&
         p.y() <= area_max_m.y();
}

bool DrivableCourt::in_net_zone(const Vec2& p) const {
  return net && std::abs(p.x()) < net->clearance_m - kEps && std::abs(p.y()) < net->end_m() - kEps;
}

bool DrivableCourt::in_net_lane(const Vec2& p) const {
  return net && std::abs(p.x()) < net->travel_clearance_m - kEps &&
         std::abs(p.y()) < net->end_m() - kEps;
}

Vec2 DrivableCourt::outside_net_zone(const Vec2& p) const {
  if (!in_net_zone(p)) return p;
  const double x_edge = net->clearance_m, y_edge = net->end_m();
  // Out through the nearer edge: a side of the net, or past a post's end.
  if (x_edge - std::abs(p.x()) <= y_edge - std::abs(p.y())) return {side_of(p) * x_edge, p.y()};
  return {p.x(), std::copysign(y_edge, p.y())};
}

Vec2 DrivableCourt::approach_point(const Vec2& ball) const {
  if (!in_net_zone(ball)) return ball;
  return {side_of(ball) * net->clearance_m, ball.y()};
}

bool DrivableCourt::blocked(const Vec2& a, const Vec2& b) const {
  if (!net) return false;
  const double y_end = net->end_m();
  if (crosses(Vec2(net->clearance_m, y_end), a, b)) return true;
  if (!crosses(Vec2(net->travel_clearance_m, y_end), a, b)) return false;
  const bool straight_away = std::abs(a.y() - b.y()) <= kEps && side_of(a) == side_of(b);
  return !straight_away;
}

DrivablePath shortest_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  if (!lexicographic_less(b, a)) return canonical_path(court, a, b);
  DrivablePath path = canonical_path(court, b, a);
  std::reverse(path.via.begin(), path.via.begin() + path.via_count);
  return path;
}

DrivableCourt drivable_court(const SiteCourt& court) {
  DrivableCourt out;
  out.area_max_m = Vec2(court.area_length_m / 2.0, court.area_width_m / 2.0);
  out.area_min_m = -out.area_max_m;
  if (court.net) {
    out.net = CourtNet{court.width_m / 2.0 + court.net_posts_outside_m, court.net_clearance_m,
                       court.net_post_clearance_m, court.net_travel_clearance_m};
  } else {
    out.net.reset();
  }
  return out;
}

}  // namespace ballsight
