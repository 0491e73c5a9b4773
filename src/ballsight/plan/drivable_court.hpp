#pragma once
// Where the collecting robot may drive: the fenced area around a tennis court, with the net
// across its middle as an obstacle the robot goes around. Travel between two points is the
// shortest drivable path: the straight segment, or a detour round the corners of the net's travel
// lane (a convex obstacle inside a convex fence: the shortest path bends only at its corners).
// The collector may reach closer to the mesh than the lane: a point between the two (where a ball
// against the net is picked up) is left and entered straight away from the net, as a robot backs
// off the net before it turns. Along the fence the same: a point nearer the fence than its lane
// is entered and left square to the fence (fence_exit), so that the body reaches a ball against
// the fence with its mouth and backs off before it turns. Field frame: origin at the court centre
// on the net line, x along the length.

#include <memory>
#include <optional>
#include <vector>

#include "ballsight/core/field_rect.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/core/site_court.hpp"

namespace ballsight {

/// The net as the robot sees it: a segment on x = 0 from post to post. The collector mouth comes
/// no closer than `clearance_m` in x (the reach keep-out); driving along the net it keeps
/// `travel_clearance_m` (the lane: half the body's width and room), and `post_clearance_m` beyond
/// each post (the body swings round it).
struct CourtNet {
  double half_length_m = 10.97 / 2.0 + 0.914;  // centre to post: ITF posts 0.914 m outside
  double clearance_m = 0.06;
  double post_clearance_m = 0.50;
  double travel_clearance_m = 0.45;
  /// The mesh and the posts reach this far either side of the plane (the simulator's posts'
  /// radius): the obstacle the body must not touch (costmap.hpp).
  double body_half_m = 0.04;

  /// How far the keep-out and the lane reach along the net from the centre line.
  double end_m() const { return half_length_m + post_clearance_m; }
  /// The travel lane as a rectangle of the field.
  FieldRect lane() const {
    return {Vec2(-travel_clearance_m, -end_m()), Vec2(travel_clearance_m, end_m())};
  }
};

class ObstacleDetours;

struct DrivableCourt {
  Vec2 area_min_m = Vec2(-18.0, -9.0);  // the fence, an axis-aligned rectangle
  Vec2 area_max_m = Vec2(18.0, 9.0);
  std::optional<CourtNet> net = CourtNet{};
  double fence_lane_m = 0.70;  // SiteCourt::fence_lane_m
  /// A point nearer the fence than this is in its lane: reached and left square to the fence,
  /// from the lane's edge (a ball farther out is reached at any angle: the body's corners stay
  /// inside the fence within the mouth's half width, and it turns on the spot after).
  double fence_square_m = 0.35;
  /// In a corner (a ball in the lanes of two sides) the mouth comes square to the nearer side,
  /// its centre at least this far from the other (the body turns on the spot there), moved along
  /// the fence from the ball by at most `corner_shift_m` (the ball still inside the mouth).
  double corner_room_m = 0.51;
  double corner_shift_m = 0.30;
  /// What stands on the court (people, bags) and the ways round it (plan/obstacle_detours.hpp);
  /// null: nothing.
  std::shared_ptr<const ObstacleDetours> obstacles;

  /// A standard court: 36 x 18 m fence centred on the court, the net of a doubles court.
  static DrivableCourt standard() { return {}; }

  /// Throws InputError naming the first invalid field (the net's keep-out must fit the fence).
  void validate() const;

  bool in_area(const Vec2& p) const;
  /// Inside the net's reach keep-out (|x| < clearance, |y| < half length + post clearance).
  bool in_net_zone(const Vec2& p) const;
  /// Inside the net's travel lane (|x| < travel clearance, |y| as the reach keep-out).
  bool in_net_lane(const Vec2& p) const;
  /// The axis (0: x, 1: y) square to the side of the fence whose lane `p` is in (nearer than
  /// fence_square_m; the nearer side in a corner); nullopt: not in the lane.
  std::optional<int> fence_side(const Vec2& p) const;
  bool in_fence_lane(const Vec2& p) const { return fence_side(p).has_value(); }
  /// Where a path from `p` leaves the fence's lane: square to that side, to the lane's edge;
  /// `p` outside the lane.
  Vec2 fence_exit(const Vec2& p) const;
  /// The segment a-b runs within 10 degrees of square to the fence's side at each end in its
  /// lane, or joins two points of one side's lane within 45 degrees of square and 25 cm along
  /// it (a robot's mouth and the ball ahead of it): driven straight in or out, with no exit.
  bool square_to_fence(const Vec2& a, const Vec2& b) const;
  /// `p`, or, inside the net's keep-out, the nearest point on its edge.
  Vec2 outside_net_zone(const Vec2& p) const;
  /// Where the robot's collector picks up a ball at `ball`: the ball itself; for a ball inside
  /// the net's keep-out, the nearest point on the keep-out's edge on the ball's side of the net;
  /// for a ball in the fence's lane within `corner_room_m` of the other side (a corner), a point
  /// moved along the nearer side away from the other.
  Vec2 approach_point(const Vec2& ball) const;
  /// The open segment a-b may not be driven: it passes through the reach keep-out, or through
  /// the lane other than straight away from the net (both ends on one side at the same y).
  bool blocked(const Vec2& a, const Vec2& b) const;
};

/// The shortest drivable path from a to b: `via` holds the points it bends at (at most two of
/// the net lane's corners, and where it leaves and enters that lane and the fence's straight
/// from and to a or b).
struct DrivablePath {
  double length_m = 0.0;
  std::vector<Vec2> via;
};

/// The fenced area (centred on the court) and the net of a site's court.
DrivableCourt drivable_court(const SiteCourt& court);

/// Shortest path between two points of the area outside the net's reach keep-out, round the
/// court's obstacles (ObstacleDetours::route).
DrivablePath shortest_path(const DrivableCourt& court, const Vec2& a, const Vec2& b);
/// The same with the obstacles not counted: round the net, and along the fence.
DrivablePath net_path(const DrivableCourt& court, const Vec2& a, const Vec2& b);

}  // namespace ballsight
