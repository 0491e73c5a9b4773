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

/// Shortest path with a before b in lexicographic order, so that a path and its reverse bend at
/// the same corners: Dijkstra over a, b and the keep-out's four corners, joined where the segment
/// between them is clear (the shortest path round a convex obstacle bends only at its corners).
DrivablePath canonical_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  DrivablePath best;
  best.length_m = (b - a).norm();
  if (!court.blocked(a, b)) return best;
  const double c = court.net->clearance_m;
  const double y_end = court.net->half_length_m + court.net->post_clearance_m;
  const std::array<Vec2, 6> node{
      a, Vec2(c, y_end), Vec2(-c, y_end), Vec2(-c, -y_end), Vec2(c, -y_end), b};
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
  best.length_m = dist[kB];
  std::array<Vec2, 4> reversed{};
  int count = 0;
  for (int v = prev[kB]; v > 0; v = prev[static_cast<std::size_t>(v)]) {
    reversed[static_cast<std::size_t>(count++)] = node[static_cast<std::size_t>(v)];
  }
  best.via_count = count;
  for (int i = 0; i < count; ++i) {
    best.via[static_cast<std::size_t>(i)] = reversed[static_cast<std::size_t>(count - 1 - i)];
  }
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
  const double y_end = net->half_length_m + net->post_clearance_m;
  require(area_min_m.x() < -net->clearance_m && area_max_m.x() > net->clearance_m &&
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
  return net && std::abs(p.x()) < net->clearance_m - kEps &&
         std::abs(p.y()) < net->half_length_m + net->post_clearance_m - kEps;
}

Vec2 DrivableCourt::outside_net_zone(const Vec2& p) const {
  if (!in_net_zone(p)) return p;
  const double x_edge = net->clearance_m, y_edge = net->half_length_m + net->post_clearance_m;
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
  const Vec2 half(net->clearance_m, net->half_length_m + net->post_clearance_m);
  // Both ends on one side of the keep-out: clear (most pairs of a court; no clipping needed).
  for (int axis = 0; axis < 2; ++axis) {
    if ((a[axis] >= half[axis] && b[axis] >= half[axis]) ||
        (a[axis] <= -half[axis] && b[axis] <= -half[axis])) {
      return false;
    }
  }
  // Liang-Barsky clip of the segment against the open keep-out rectangle.
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

DrivablePath shortest_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  if (!lexicographic_less(b, a)) return canonical_path(court, a, b);
  DrivablePath path = canonical_path(court, b, a);
  std::reverse(path.via.begin(), path.via.begin() + path.via_count);
  return path;
}

}  // namespace ballsight
