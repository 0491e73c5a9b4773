#include "ballsight/plan/drivable_court.hpp"

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
/// the same corners.
DrivablePath canonical_path(const DrivableCourt& court, const Vec2& a, const Vec2& b) {
  DrivablePath best;
  best.length_m = (b - a).norm();
  if (!court.blocked(a, b)) return best;
  const double c = court.net->clearance_m;
  const double y_end = court.net->half_length_m + court.net->post_clearance_m;
  best.length_m = INFINITY;
  for (const double end : {1.0, -1.0}) {
    DrivablePath path;
    path.via = {Vec2(side_of(a) * c, end * y_end), Vec2(side_of(b) * c, end * y_end)};
    path.via_count = path.via[0] == path.via[1] ? 1 : 2;
    if (path.via_count == 2 && !court.blocked(a, path.via[1])) {
      path.via[0] = path.via[1];
      path.via_count = 1;
    } else if (path.via_count == 2 && !court.blocked(path.via[0], b)) {
      path.via_count = 1;
    }
    Vec2 from = a;
    bool clear = true;
    for (int i = 0; i < path.via_count; ++i) {
      clear = clear && !court.blocked(from, path.via[static_cast<std::size_t>(i)]);
      path.length_m += (path.via[static_cast<std::size_t>(i)] - from).norm();
      from = path.via[static_cast<std::size_t>(i)];
    }
    clear = clear && !court.blocked(from, b);
    path.length_m += (b - from).norm();
    if (clear && path.length_m < best.length_m - kEps) best = path;
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
  if (path.via_count == 2) std::swap(path.via[0], path.via[1]);
  return path;
}

}  // namespace ballsight
