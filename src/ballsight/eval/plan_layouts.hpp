#pragma once
// Simulated ball layouts on a standard tennis court for route planning: where balls lie after
// play. Field frame as everywhere (origin at the court centre on the net line, x along the
// length); the fenced area is 36 x 18 m.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "ballsight/plan/planning_problem.hpp"

namespace ballsight::eval {

enum class BallLayout {
  uniform,   // anywhere in the fenced area
  practice,  // clustered as after practice: along both baselines and in front of the net
  net,       // within 3 m of the net on both sides: most legs cross it
};

inline constexpr BallLayout kBallLayouts[] = {BallLayout::uniform, BallLayout::practice,
                                              BallLayout::net};

std::string_view layout_name(BallLayout layout);
std::optional<BallLayout> layout_from_name(std::string_view name);

/// `n` balls of `layout` on the standard court (none inside the net, none closer than a ball's
/// diameter to another), and the robot at a random drivable pose; the same seed, the same problem.
PlanningProblem court_planning_problem(BallLayout layout, int n, std::uint64_t seed);

}  // namespace ballsight::eval
