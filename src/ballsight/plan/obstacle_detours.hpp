#pragma once
// The ways round what stands on the court (a person, a bag: the world model's obstacles, each as
// the circle round its footprint). A path from a to b is the one round the net and along the fence
// (net_path) when it keeps its distance from every obstacle; else the shortest one through the
// corners of a polygon round each obstacle (a visibility graph: the shortest path among convex
// obstacles bends only at their corners), each leg itself a net_path. The corners' distances to
// one another are found once, when the obstacles are set (Floyd-Warshall over a few dozen
// corners); a path then only joins a and b to the corners they see.
//
// The robot's centre keeps `keep_m` beyond an obstacle's circle: half its body's diagonal and
// room. A point within that (a ball beside a bag) is left and entered straight away from the
// obstacle's centre, as a ball against the net is.

#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/drivable_court.hpp"

namespace ballsight {

/// An obstacle as the planner sees it: the circle round its footprint.
struct ObstacleDisc {
  Vec2 center_m = Vec2::Zero();
  double radius_m = 0.0;
};

class ObstacleDetours {
 public:
  /// `court`'s ways round `discs` (court's own obstacles are not counted); throws InputError
  /// naming an invalid disc.
  ObstacleDetours(const DrivableCourt& court, std::vector<ObstacleDisc> discs, double keep_m);

  const std::vector<ObstacleDisc>& discs() const { return discs_; }
  double keep_m() const { return keep_m_; }
  /// The shortest way from a to b on `court` (the court these detours were made for) round the
  /// discs; the way round the net alone when no way round them is found.
  DrivablePath route(const DrivableCourt& court, const Vec2& a, const Vec2& b) const;

 private:
  /// `p`, or, within a disc's keep-out, where a path from it leaves that: straight away from the
  /// disc's centre.
  Vec2 exit_of(const Vec2& p) const;
  /// Whether the path from a through path.via to b keeps out of every disc's keep-out.
  bool clear(const Vec2& a, const DrivablePath& path, const Vec2& b) const;

  std::vector<ObstacleDisc> discs_;
  double keep_m_;
  std::vector<Vec2> corners_;
  std::vector<double> distance_;    // corners x corners: the shortest way between two
  std::vector<int> next_;           // the first corner after the start on it (-1: none)
  std::vector<DrivablePath> legs_;  // corners x corners: the direct leg, when clear
};

/// Whether `p` lies on the collector's body at `pose` (0.30 m ahead and behind, 0.35 m either
/// side) or within 10 cm of it: an obstacle centred there is the robot itself, seen when the
/// cameras missed its markers.
bool on_robot_body(const Pose2D& pose, const Vec2& p);

/// `court` with `discs` on it (none: as it was).
DrivableCourt with_obstacles(DrivableCourt court, std::vector<ObstacleDisc> discs,
                             double keep_m = 0.5);

}  // namespace ballsight
