#pragma once
// The simulated court of a seed, as `serve --sim`, `camera-node --sim` and `court-node --sim` all
// see it: the rig and its site, the scene (balls, robot, light), and each camera's renderer under
// the scene's light. A frame depends on the scene, the camera and the vision tick alone (fresh
// sensor noise per tick), so that camera nodes in separate processes render exactly the frames
// one process would.

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

/// The simulated court's size and net as a site file gives them.
SiteCourt site_court(const sim::TennisCourtSpec& court);

/// The site file a user of the simulated court would write: court size, the reference balls'
/// floor positions, the colours, and each camera's pole corner as a rough position hint (5 m
/// high, at the corner of the run-off area; not the simulator's exact pose).
Site simulated_site(const sim::CourtRig& rig);

struct SimulatedCourtOptions {
  std::uint64_t seed = 1;
  std::optional<int> balls;     // tennis balls on the court; nullopt: the scenario's 20-60
  double cluster_share = 0.25;  // of them, in clusters of 2-4 touching balls
  sim::BallLayout layout = sim::BallLayout::scattered;  // where the others lie
  sim::ObstacleOptions obstacles;                       // people and bags (none by default)
  /// Changes the drawn scene before the court begins (a test's or an experiment's own layout);
  /// the scene must stay valid.
  std::function<void(sim::CourtScene&)> arrange;
};

class SimulatedCourt {
 public:
  explicit SimulatedCourt(const SimulatedCourtOptions& options);

  const sim::CourtRig& rig() const { return rig_; }
  const Site& site() const { return site_; }
  /// The scene as the court begins (the robot where it starts, every ball on the court).
  const sim::CourtScene& scene() const { return scene_; }
  /// Every camera as the pipeline uses it (the simulator's calibration), in site order.
  std::vector<FieldCamera> cameras() const;
  /// Camera `camera`'s view of the court with nothing on it, under the scene's light and exposure
  /// (its own sensor noise): the view an installation takes once when it is set up, against which
  /// the pipeline finds obstacles (detect/court_foreground.hpp).
  cv::Mat empty_court(std::size_t camera) const;
  /// Camera `camera`'s frame of `scene` (this court's scene as it is now) at vision tick `tick`.
  cv::Mat render(std::size_t camera, const sim::CourtScene& scene, std::uint64_t tick) const;

 private:
  std::uint64_t seed_;
  sim::CourtRig rig_;
  Site site_;
  sim::CourtScene scene_;
  std::vector<sim::CourtRenderer> renderers_;
  std::vector<cv::Mat> lit_;  // each camera's background under the scene's (fixed) lighting
};

}  // namespace ballsight
