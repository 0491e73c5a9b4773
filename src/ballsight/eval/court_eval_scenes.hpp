#pragma once
// The simulated court of the court evaluations (`eval court`, `eval tennis-sim`): the rig and the
// scenes one seed gives, each rendered by every camera with its truth. One seed, the same scenes
// in both evaluations, and any scene can be rendered again on its own.

#include <cstdint>
#include <vector>

#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/court_truth.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight {

/// The seeds an evaluation with seed `seed` derives for the rig, for the calibration images and
/// for scene `scene` (0-based).
std::uint64_t court_eval_rig_seed(std::uint64_t seed);
std::uint64_t court_eval_calibration_seed(std::uint64_t seed);
std::uint64_t court_eval_scene_seed(std::uint64_t seed, int scene);

/// Scene k of an evaluation: the scene, each camera's view (its noise seeded from the scene's
/// seed and the camera's index) and the truth of every sphere in every view.
struct RenderedCourtScene {
  sim::CourtScene scene;
  std::vector<sim::CourtRender> renders;  // per camera
  std::vector<sim::SphereTruth> truth;    // per sphere of scene.spheres()
};

class CourtEvalScenes {
 public:
  /// The rig of seed `seed` and a renderer per camera (a ray table each: about a second at
  /// 1920x1080).
  CourtEvalScenes(const sim::TennisCourtSpec& court, const sim::CourtRigOptions& rig,
                  std::uint64_t seed);

  const sim::CourtRig& rig() const { return rig_; }
  RenderedCourtScene render(const sim::CourtScenarioOptions& scenario, int scene) const;

 private:
  std::uint64_t seed_;
  sim::CourtRig rig_;
  std::vector<sim::CourtRenderer> renderers_;
};

}  // namespace ballsight
