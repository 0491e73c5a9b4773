#include "ballsight/plan/drivable_court.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/plan/obstacle_detours.hpp"

namespace ballsight {
namespace {

constexpr double kEps = 1e-9;
constexpr double kSquareTan = 0.1763;  // "square to the fence": within 10 degrees
// Two points in one side's lane this close along it: the nearer one ahead of the mouth of a robot
// at the other (still inside the mouth), reached straight.
constexpr double kMouthReachM = 0.25;

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

/// Round the net: the shortest path with a before b in lexicographic order, so that a path and
/// its reverse bend at the same points: out of the lane straight from a, Dijkstra over that exit,
/// the lane's four corners and b's exit, joined where the segment between them is clear (the
/// shortest path round a convex obstacle bends only at its corners), and into the lane straight
/// to b.
DrivablePath canonical_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  DrivablePath best;
  const auto add = [&best](const Vec2& p) { best.via.push_back(p); };
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
  require(std::isfinite(fence_lane_m) && fence_lane_m >= 0.0, "fence_lane_m",
          "must not be negative");
  require(std::isfinite(fence_square_m) && fence_square_m >= 0.0 && fence_square_m <= fence_lane_m,
          "fence_square_m", "must be in [0, fence_lane_m]");
  require(std::isfinite(corner_room_m) && corner_room_m >= 0.0, "corner_room_m",
          "must not be negative");
  require(std::isfinite(corner_shift_m) && corner_shift_m >= 0.0, "corner_shift_m",
          "must not be negative");
  if (!net) return;
  require(net->half_length_m > 0.0, "net.half_length_m", "must be positive");
  require(net->clearance_m >= 0.0, "net.clearance_m", "must not be negative");
  require(net->post_clearance_m >= 0.0, "net.post_clearance_m", "must not be negative");
  require(std::isfinite(net->body_half_m) && net->body_half_m >= 0.0, "net.body_half_m",
          "must not be negative");
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
  if (in_net_zone(ball)) return {side_of(ball) * net->clearance_m, ball.y()};
  const std::optional<int> square = fence_side(ball);
  if (!square) return ball;
  // Square to the nearer side; along it, away from the other side if it is near (a corner).
  const int along = 1 - *square;
  const double low = area_min_m[along], high = area_max_m[along];
  Vec2 point = ball;
  if (ball[along] - low < high - ball[along]) {
    point[along] =
        std::max(ball[along], std::min(low + corner_room_m, ball[along] + corner_shift_m));
  } else {
    point[along] =
        std::min(ball[along], std::max(high - corner_room_m, ball[along] - corner_shift_m));
  }
  return point;
}

std::optional<int> DrivableCourt::fence_side(const Vec2& p) const {
  std::optional<int> side;
  double nearest = INFINITY;
  for (int axis = 0; axis < 2; ++axis) {
    if (area_max_m[axis] - area_min_m[axis] <= 2.0 * fence_lane_m) continue;  // no room for one
    const double depth = std::min(p[axis] - area_min_m[axis], area_max_m[axis] - p[axis]);
    if (depth < fence_square_m && depth < nearest) {
      nearest = depth;
      side = axis;
    }
  }
  return side;
}

Vec2 DrivableCourt::fence_exit(const Vec2& p) const {
  const std::optional<int> axis = fence_side(p);
  if (!axis) return p;
  Vec2 out = p;
  out[*axis] =
      std::clamp(p[*axis], area_min_m[*axis] + fence_lane_m, area_max_m[*axis] - fence_lane_m);
  return out;
}

bool DrivableCourt::square_to_fence(const Vec2& a, const Vec2& b) const {
  const Vec2 d = b - a;
  const std::optional<int> a_side = fence_side(a);
  if (a_side && a_side == fence_side(b) && std::abs(d[1 - *a_side]) <= kMouthReachM &&
      std::abs(d[1 - *a_side]) <= std::abs(d[*a_side])) {
    return true;
  }
  for (const Vec2& p : {a, b}) {
    if (const std::optional<int> axis = fence_side(p);
        axis && std::abs(d[1 - *axis]) > kSquareTan * std::abs(d[*axis])) {
      return false;
    }
  }
  return true;
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
  return court.obstacles ? court.obstacles->route(court, a, b) : net_path(court, a, b);
}

DrivablePath net_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  // Round the net, in the canonical order.
  const auto round_net = [&court](const Vec2& from, const Vec2& to) {
    if (!lexicographic_less(to, from)) return canonical_path(court, from, to);
    DrivablePath path = canonical_path(court, to, from);
    std::reverse(path.via.begin(), path.via.end());
    return path;
  };
  const Vec2 a_out = court.fence_exit(a), b_out = court.fence_exit(b);
  if ((a_out == a && b_out == b) || (court.square_to_fence(a, b) && !court.blocked(a, b))) {
    return round_net(a, b);
  }
  // Out of the fence's lane square to it, round the net, and into the lane square to it (in a
  // corner the exit leaves one side's lane only: the approach point leaves the body room there).
  DrivablePath path;
  if (a_out != a) path.via.push_back(a_out);
  const DrivablePath inner = round_net(a_out, b_out);
  path.via.insert(path.via.end(), inner.via.begin(), inner.via.end());
  if (b_out != b) path.via.push_back(b_out);
  path.length_m = (a_out - a).norm() + inner.length_m + (b - b_out).norm();
  return path;
}

DrivableCourt drivable_court(const SiteCourt& court) {
  DrivableCourt out;
  out.area_max_m = Vec2(court.area_length_m / 2.0, court.area_width_m / 2.0);
  out.area_min_m = -out.area_max_m;
  out.fence_lane_m = court.fence_lane_m;
  out.fence_square_m = std::min(out.fence_square_m, court.fence_lane_m);  // 0: no lane
  if (court.net) {
    out.net = CourtNet{court.width_m / 2.0 + court.net_posts_outside_m, court.net_clearance_m,
                       court.net_post_clearance_m, court.net_travel_clearance_m};
  } else {
    out.net.reset();
  }
  return out;
}

}  // namespace ballsight
