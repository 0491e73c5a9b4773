#pragma once
// A planned route on the court from above: the court, the net and its keep-out, the balls (grey:
// out of reach), the robot's collector and heading, and each route as a coloured path with its
// visiting order numbered.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/viz/court_map.hpp"

namespace ballsight {

struct RouteLayer {
  std::string label;  // e.g. "ballsight 231.4 s"
  cv::Scalar colour;
  Route route;
};

/// The map, on `floor` when the problem has a court (its net drawn where the drivable court has
/// one); without a court the view fits the points (a plain point problem).
cv::Mat draw_route_map(const PlanningProblem& problem, const CourtFloor& floor,
                       const std::vector<RouteLayer>& layers, const std::string& title,
                       double pixels_per_m = 32.0);

}  // namespace ballsight
