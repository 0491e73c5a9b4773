#pragma once
// A planned route on the court from above: the court, the net and its keep-out, the balls (grey:
// out of reach), the robot's collector and heading, and each route as a coloured path with its
// visiting order numbered.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/plan/planning_problem.hpp"

namespace ballsight {

struct RouteLayer {
  std::string label;  // e.g. "ballsight 231.4 s"
  cv::Scalar colour;
  Route route;
};

/// The map; without a court the view fits the points (a plain point problem).
cv::Mat draw_route_map(const PlanningProblem& problem, const std::vector<RouteLayer>& layers,
                       const std::string& title, double pixels_per_m = 32.0);

}  // namespace ballsight
