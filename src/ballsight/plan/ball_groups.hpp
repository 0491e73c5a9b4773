#pragma once
// Balls the collector takes in one pass: groups whose every ball lies within a radius of the
// group's centre, so that the mouth passing over the centre picks them all up. Measured against
// visiting every ball and against the world model's collection sites (docs/route-planning.md):
// on dense layouts (hundreds of balls after practice) planning over groups saves a fifth of the
// time, on sparse ones the groups are single balls and nothing changes.

#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct BallGroup {
  Vec2 centre_m = Vec2::Zero();  // mean of its balls
  double radius_m = 0.0;         // farthest ball from the centre
  std::vector<int> balls;        // indices into the points given
};

/// Greedy grouping of `which` (indices into `points`) in (x, y) order: each group starts at the
/// first ungrouped ball and takes its nearest ungrouped neighbours while every member stays
/// within `max_radius_m` of the group's mean.
std::vector<BallGroup> group_balls(const std::vector<Vec2>& points, const std::vector<int>& which,
                                   double max_radius_m);

}  // namespace ballsight
