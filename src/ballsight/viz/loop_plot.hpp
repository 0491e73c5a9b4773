#pragma once
// Pictures of a closed-loop run: the court from above with the robot's true path, the published
// route at a few moments, and the balls coloured by when they were collected (grey with a red
// cross: never); and the per-update latency at the robot. eval/plot_inputs.hpp reads a run's
// record (service/loop_truth.hpp) into LoopMapInput.

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/viz/court_map.hpp"

namespace ballsight {

/// What the map of a run shows; field frame, metres, simulated seconds.
struct LoopMapInput {
  struct PublishedRoute {
    double time_s = 0.0;
    std::vector<Vec2> waypoints_m;
  };
  struct Ball {
    Vec2 position_m = Vec2::Zero();
    std::optional<double> collected_s;  // nullopt: never collected
  };
  Pose2D robot_start;
  std::vector<Vec2> path_m;            // the robot's true positions after the start, in order
  std::vector<PublishedRoute> routes;  // of two waypoints or more, in the order published
  std::vector<Ball> balls;             // as the scene began
  double duration_s = 0.0;             // the run's last moment
};

/// The run drawn on `floor`, `route_snapshots` (at most 4) of its routes evenly spaced over it;
/// the view is a standard court's 36 x 18 m fence and a metre round it.
cv::Mat draw_loop_map(const CourtFloor& floor, const LoopMapInput& run, const std::string& title,
                      int route_snapshots = 4);

/// Latency (ms) of each update at the robot against its sequence number.
cv::Mat draw_latency_chart(const std::vector<std::uint64_t>& seqs,
                           const std::vector<double>& latency_ms, const std::string& title);

}  // namespace ballsight
