#pragma once
// The values a route planner works on and returns: the robot and the balls on the drivable court
// (PlanningProblem), how to plan (PlannerOptions) and the result (Route). Plain structs; the
// planner knows nothing of cameras or networks.

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/drivable_court.hpp"

namespace ballsight {

/// What the route's time is made of: driving at `max_speed_mps` and turning on the spot at
/// `turn_rate_dps` (a small differential-drive collector).
struct RobotLimits {
  double max_speed_mps = 1.0;
  double turn_rate_dps = 90.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// A basket that holds `balls` balls, emptied at `unload_m`: visited when full (or before, when
/// the next place's balls would not fit) and, with `unload_at_end`, at the end. It holds `held`
/// balls when the route begins.
struct Capacity {
  int balls = 0;
  Vec2 unload_m = Vec2::Zero();
  int held = 0;
  bool unload_at_end = true;
};

inline constexpr std::size_t kMaxBalls = 2000;  // a court holds a few hundred
inline constexpr double kMaxCoordinateM = 1e6;  // far beyond any field, far below overflow

struct PlanningProblem {
  /// The pose of the robot's collector mouth (its front), where every distance is measured from.
  Pose2D robot;
  std::vector<Vec2> balls;             // field frame
  std::optional<DrivableCourt> court;  // nullopt: an unbounded plane without a net
  RobotLimits limits;
  double collector_width_m = 0.70;  // the report's collector (section 7.8); 0: visit every centre
  double ball_radius_m = 0.0335;
  double sweep_margin_m = 0.05;  // kept between a ball and the collector's edge
  std::optional<Capacity> capacity;
  std::optional<Vec2> return_to;  // an open route (no return) when absent

  /// Throws InputError naming what is wrong: a NaN or huge coordinate, more than kMaxBalls balls,
  /// two balls at one place, the robot inside the net or outside the area, a capacity below 1.
  /// Balls outside the area are not an error: the route reports them unreachable.
  void validate() const;
  /// How far from a ball the collector mouth's centre line may pass and still pick it up.
  double sweep_radius_m() const;
};

enum class PlannerKind { priority, nearest, ballsight, exact };
enum class CostKind { time, distance };

std::string_view planner_name(PlannerKind kind);
/// "priority", "nearest", "ballsight", "exact"; nullopt for anything else.
std::optional<PlannerKind> planner_from_name(std::string_view name);

/// Section 7.11 of the tennis-ball report: priority = W1 * distance_cm + W2 * |angle_deg|. The
/// report prints no weights; its Figure 8.2 (four balls with distance, angle and priority) is
/// fitted exactly by W1 = 0.35, W2 = 0.65 (tests/plan/priority_planner_test.cpp).
struct PriorityWeights {
  double per_cm = 0.35;
  double per_deg = 0.65;

  double priority(double distance_cm, double angle_deg) const {
    return per_cm * distance_cm + per_deg * std::abs(angle_deg);
  }
};

struct Route;

struct PlannerOptions {
  PlannerKind kind = PlannerKind::ballsight;
  CostKind cost = CostKind::time;
  double effort = 1.0;  // ballsight: scales the improvement search (kicks of iterated search)
  std::uint64_t seed = 1;
  bool sweep = true;  // ballsight: pass balls at the collector's side instead of over their centre
  PriorityWeights priority;
  /// Re-planning: the route being driven. Its order is the warm start, and its next target is
  /// kept unless switching saves more than `target_switch_margin_s` (or metres for distance).
  const Route* previous = nullptr;
  double target_switch_margin_s = 1.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct Route {
  std::string planner;
  std::vector<int> order;         // indices into the problem's balls, visiting order
  std::vector<Vec2> targets_m;    // those balls' positions, in visiting order
  std::vector<Vec2> visits_m;     // where the collector mouth passes for each of them
  std::vector<int> unload_after;  // with a capacity: positions in `order` after which it unloads
  std::optional<Vec2> unload_m;   // with a capacity: where it unloads
  std::vector<Vec2> waypoints_m;  // the path: start, visits, detours round the net, unloads, end
  std::vector<int> unreachable;   // balls outside the drivable area, not in `order`
  double length_m = 0.0;
  double time_s = 0.0;
  double plan_ms = 0.0;

  /// The route empties the basket before its next ball (unload_after begins with -1).
  bool unloads_first() const { return !unload_after.empty() && unload_after.front() == -1; }
};

}  // namespace ballsight
