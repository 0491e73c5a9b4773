#pragma once
// The drivable court as a costmap, after ROS 2 Nav2's costmap_2d (docs.nav2.org, "Costmap 2D"):
// a grid over the fenced area whose cells hold the distance to the nearest obstacle, the net's
// mesh and posts or the fence, so that a local planner tells at once how far any point of the
// robot's body is from touching one. What stands on the court and moves (people, bags: the world
// model's obstacles, as discs) is a layer over the grid, as Nav2's obstacle layer is over its
// static one: a few discs, measured exactly at each query and replaced with every update. Nav2
// inflates lethal cells by the robot's radius; here the robot's outline is checked against the
// distances (robot/local_planner.hpp), which is the same test for a round robot and an exact one
// for the collector's rectangle.

#include <cstddef>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/drivable_court.hpp"
#include "ballsight/plan/obstacle_detours.hpp"

namespace ballsight {

class Costmap {
 public:
  /// The court's obstacles on cells of `resolution_m` (a few centimetres: the error of a
  /// distance read between cells is a fraction of it).
  explicit Costmap(const DrivableCourt& court, double resolution_m = 0.05);

  /// The distance from `p` to the nearest obstacle, metres, read bilinearly between cell
  /// centres: negative inside one (beyond the fence, in the net); beyond the grid, negative.
  double clearance(const Vec2& p) const;

  double resolution_m() const { return resolution_m_; }
  /// The obstacles' layer: these discs from now on (the court's own when made).
  void set_obstacles(std::vector<ObstacleDisc> discs) { discs_ = std::move(discs); }
  const std::vector<ObstacleDisc>& obstacles() const { return discs_; }

 private:
  std::size_t index(int col, int row) const;  // into distance_m_
  double cell(int col, int row) const;

  Vec2 origin_;  // the centre of cell (0, 0)
  double resolution_m_;
  int cols_ = 0, rows_ = 0;
  std::vector<float> distance_m_;  // row-major
  std::vector<ObstacleDisc> discs_;
};

}  // namespace ballsight
