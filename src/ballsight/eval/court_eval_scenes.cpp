#include "ballsight/eval/court_eval_scenes.hpp"

#include "ballsight/sim/seeding.hpp"

namespace ballsight {

namespace {

// Independent random streams of one evaluation seed.
enum Stream : std::uint64_t { kRigStream, kCalibrationStream, kSceneStream = 1000 };

}  // namespace

std::uint64_t court_eval_rig_seed(std::uint64_t seed) {
  return sim::derive_seed(seed, kRigStream);
}

std::uint64_t court_eval_calibration_seed(std::uint64_t seed) {
  return sim::derive_seed(seed, kCalibrationStream);
}

std::uint64_t court_eval_scene_seed(std::uint64_t seed, int scene) {
  return sim::derive_seed(seed, kSceneStream + static_cast<std::uint64_t>(scene));
}

CourtEvalScenes::CourtEvalScenes(const sim::TennisCourtSpec& court, const sim::CourtRigOptions& rig,
                                 std::uint64_t seed)
    : seed_(seed), rig_(sim::make_court_rig(court, rig, court_eval_rig_seed(seed))) {
  for (const sim::CourtCamera& camera : rig_.cameras) renderers_.emplace_back(camera, rig_.court);
}

RenderedCourtScene CourtEvalScenes::render(const sim::CourtScenarioOptions& scenario,
                                           int scene) const {
  const std::uint64_t scene_seed = court_eval_scene_seed(seed_, scene);
  RenderedCourtScene rendered{sim::make_court_scene(rig_.court, scenario, scene_seed), {}, {}};
  for (std::size_t c = 0; c < renderers_.size(); ++c)
    rendered.renders.push_back(
        renderers_[c].render(rendered.scene, sim::derive_seed(scene_seed, c)));
  rendered.truth = sim::court_scene_truth(rig_, rendered.scene, rendered.renders);
  return rendered;
}

}  // namespace ballsight
