#include "ballsight/eval/simulated_court.hpp"

#include "ballsight/eval/court_eval_calibration.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight {
namespace {

sim::CourtScene make_scene(const sim::CourtRig& rig, const SimulatedCourtOptions& options) {
  sim::CourtScenarioOptions scenario;
  scenario.ball_count = options.balls;
  scenario.cluster_share = options.cluster_share;
  sim::CourtScene scene =
      sim::make_court_scene(rig.court, scenario, sim::derive_seed(options.seed, 1));
  scene.effects.quantile_noise = true;  // 40 views a simulated second
  return scene;
}

}  // namespace

SimulatedCourt::SimulatedCourt(const SimulatedCourtOptions& options)
    : seed_(options.seed),
      rig_(sim::make_court_rig({}, {}, sim::derive_seed(options.seed, 0))),
      site_(simulated_site(rig_)),
      scene_(make_scene(rig_, options)) {
  for (const sim::CourtCamera& c : rig_.cameras) {
    renderers_.emplace_back(c, rig_.court);
    lit_.push_back(renderers_.back().lit_background(scene_.lighting, scene_.leaves));  // one sun
  }
}

std::vector<FieldCamera> SimulatedCourt::cameras() const {
  std::vector<FieldCamera> cameras;
  for (const sim::CourtCamera& c : rig_.cameras) cameras.push_back({c.camera, c.camera_from_field});
  return cameras;
}

cv::Mat SimulatedCourt::render(std::size_t camera, const sim::CourtScene& scene,
                               std::uint64_t tick) const {
  return renderers_[camera]
      .render(scene, sim::derive_seed(seed_ + tick, camera + 2), lit_[camera])
      .bgr;
}

}  // namespace ballsight
