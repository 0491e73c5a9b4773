#pragma once
// People and bags on the simulated court (court_scene.hpp's CourtObstacle), drawn for a seed: a
// person standing, a tennis bag left on the floor, a person walking slowly across the court. They
// stand clear of the balls, the robot, the net's lane and the fence's, so that every ball stays
// reachable round them.

#include <cstdint>
#include <string>
#include <string_view>

#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

struct ObstacleOptions {
  int people = 0;   // standing still
  int bags = 0;     // on the floor
  int walkers = 0;  // walking at 0.3 m/s from one side of the court to the other and back
  /// An obstacle's edge is at least this far from every ball's centre and 1.5 m from the
  /// robot's, its centre 1.2 m from the net's plane and the fence.
  double ball_gap_m = 0.5;

  int count() const { return people + bags + walkers; }
  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// "none", or a comma-separated list of person, bag and walker (each as often as wanted: up to
/// four of each); throws InputError naming `option` and what is wrong.
ObstacleOptions parse_obstacles(std::string_view list, const std::string& option);

/// Adds `options`' obstacles to `scene` (after its balls and robot are placed); deterministic for
/// a seed, and independent of the scene's other draws.
void add_obstacles(CourtScene& scene, const TennisCourtSpec& court, const ObstacleOptions& options,
                   std::uint64_t seed);

}  // namespace ballsight::sim
