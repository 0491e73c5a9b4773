#pragma once
// Seeded generation of court scenes for testing the court pipeline: 20-60 tennis balls, some in
// tight clusters of touching balls and some right next to the robot (so that the robot hides them
// from some cameras), reference balls at line intersections, a random robot pose, a random sun,
// a shadow band across the court (sun, hard shadow or overcast light; indoor light when asked),
// worn balls, a brightness change, fallen leaves, a water bottle, people and bags, and sensor
// noise.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "ballsight/sim/court_obstacles.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

/// Where the balls that are neither in clusters nor beside the robot lie: scattered (mostly on
/// the court, some in the run-off), in a line along the net (within 30 cm of its centre line,
/// both sides), along the fence (within 20 cm of it), or around the net posts (within 60 cm).
enum class BallLayout { scattered, along_net, along_fence, net_posts };

/// "scattered", "along_net", "along_fence", "net_posts".
std::string_view ball_layout_name(BallLayout layout);

struct CourtScenarioOptions {
  std::optional<int> ball_count;              // tennis balls; nullopt: uniform in [20, 60]
  double noise_sigma = 2.0;                   // sensor noise, grey levels
  std::optional<double> brightness_gain;      // nullopt: uniform in [0.8, 1.2]
  bool shadow = true;                         // a shadow band across the court (sun, hard_shadow)
  double cluster_share = 0.25;                // of the balls, those in clusters of 2-4 touching
  BallLayout layout = BallLayout::scattered;  // the other balls
  /// nullopt: each scene draws sun, hard_shadow or overcast, equally likely (indoor only when
  /// asked: the scenes of a seed stay as they were).
  std::optional<LightCondition> light;
  /// Of a scene's balls, up to this share (drawn per scene) are worn: their felt paled towards
  /// grey by 25-55 %.
  double worn_share_max = 0.4;
  /// Things of a ball's colour that are not balls: on about half the scenes 3-12 fallen leaves
  /// (most of them yellow-green), on about a quarter a yellow-green water bottle standing.
  /// Off by default: the court detector does not reject all of them yet (docs/court-eval.md).
  bool distractors = false;
  /// Every frame saved as a JPEG of this quality and decoded (ImageEffects::jpeg_quality); 0:
  /// none.
  int jpeg_quality = 0;
  /// Every frame smeared by this many pixels (ImageEffects::motion_blur_px), in a direction
  /// drawn per scene; 0: none. Drawn last, so that the scenes of a seed stay as they were.
  double motion_blur_px = 0.0;
  /// People and bags on the court (court_obstacles.hpp), drawn from a stream of their own: the
  /// rest of a seed's scene stays as it was. None by default.
  ObstacleOptions obstacles;

  static constexpr int kMaxBalls = 200;
  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Twelve reference-ball centres (z = radius) at line intersections, known to the user: the four
/// corners of the singles court, the four ends of the service lines, the two service-line T's and
/// the two points where the net line crosses the doubles sidelines. Each corner camera has six of
/// them within about 19 m, spread over its half of the court (a 2 cm ball is ~1 px in radius
/// there at 1280x720), and sees the other six further away.
std::vector<Vec3> reference_ball_positions(const TennisCourtSpec& court);

/// A scene on `court`; deterministic for a seed.
CourtScene make_court_scene(const TennisCourtSpec& court, const CourtScenarioOptions& options,
                            std::uint64_t seed);

}  // namespace ballsight::sim
