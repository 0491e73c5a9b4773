#pragma once
// The cost of driving a sequence of nodes (0 the robot, then the places to visit): every leg is
// the shortest drivable path (drivable_court.hpp), and a robot that turns on the spot pays for
// the change of direction at every node and at every bend of a detour. With a time cost a leg
// costs length / speed and a turn |angle| / turn rate; with a distance cost turns are free.
//
// The route searches (path_search.hpp) use any model with this shape:
//   int size() const;                      number of nodes
//   double leg(int a, int b) const;        driving a -> b
//   double turn(int a, int b, int c) const turning at b, arriving from a, leaving to c;
//                                          a == kHeading: the start's heading, c == kNone: none
// Turn costs are symmetric (turn(a, b, c) == turn(c, b, a)), so reversing a stretch of the path
// changes costs only at its ends.

#include <cmath>
#include <optional>
#include <vector>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/drivable_court.hpp"
#include "ballsight/plan/planning_problem.hpp"

namespace ballsight {

inline constexpr int kHeading = -1;  // "arriving" at the start along the robot's heading
inline constexpr int kNone = -2;     // nothing after the last node

class TravelModel {
 public:
  /// Nodes: `nodes[0]` is the robot at `start_heading_rad`; legs avoid `court`'s net when given.
  TravelModel(std::vector<Vec2> nodes, double start_heading_rad,
              const std::optional<DrivableCourt>& court, const RobotLimits& limits, CostKind cost);

  int size() const { return n_; }
  const Vec2& node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }

  double leg(int a, int b) const { return at(a, b).cost; }
  double length_m(int a, int b) const { return at(a, b).length_m; }
  double turn(int a, int b, int c) const {
    return turn_weight_ == 0.0 ? 0.0 : turn_weight_ * turn_rad(a, b, c);
  }
  /// The angle turned at b (0 where a leg has no direction: two nodes at one place).
  double turn_rad(int a, int b, int c) const {
    if (c == kNone) return 0.0;
    const Leg& out = at(b, c);
    if (out.length_m == 0.0 || (a != kHeading && at(a, b).length_m == 0.0)) return 0.0;
    const double in = a == kHeading ? start_heading_rad_ : at(a, b).arrive_rad;
    const double d = std::abs(out.depart_rad - in);  // both in [-pi, pi]
    return d > kPi ? 2.0 * kPi - d : d;
  }

  /// Length (m) and time (s) of driving the nodes in this order from the start's heading.
  double path_length_m(const std::vector<int>& path) const;
  double path_time_s(const std::vector<int>& path) const;

  /// The angle between two headings, in [0, pi].
  static double turn_angle_rad(double a_rad, double b_rad);

 private:
  struct Leg {
    double cost = 0.0;
    double length_m = 0.0;
    double depart_rad = 0.0;  // direction leaving a
    double arrive_rad = 0.0;  // direction arriving at b
    double bend_rad = 0.0;    // turning at the detour's corners
  };
  const Leg& at(int a, int b) const { return legs_[static_cast<std::size_t>(a * n_ + b)]; }

  std::vector<Vec2> nodes_;
  int n_ = 0;
  double start_heading_rad_ = 0.0;
  double length_weight_ = 1.0;
  double turn_weight_ = 0.0;
  double time_per_m_ = 1.0;
  double time_per_rad_ = 0.0;
  std::vector<Leg> legs_;
};

/// A model over a given symmetric cost matrix without turns (TSPLIB instances).
class MatrixModel {
 public:
  explicit MatrixModel(std::vector<std::vector<double>> cost);
  int size() const { return static_cast<int>(cost_.size()); }
  double leg(int a, int b) const {
    return cost_[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
  }
  double turn(int, int, int) const { return 0.0; }

 private:
  std::vector<std::vector<double>> cost_;
};

}  // namespace ballsight
