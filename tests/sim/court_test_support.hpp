#pragma once
// Shared by the court simulator tests: one rig and its renderers (on the court with its net, and
// on one without), built once per test program (each camera's ray table takes a fraction of a
// second), and helpers to render a scene in every camera.

#include <cstdint>
#include <vector>

#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/court_truth.hpp"

namespace ballsight::sim::test_support {

inline constexpr std::uint64_t kRigSeed = 20240611;

struct CourtFixture {
  CourtRig rig;
  std::vector<CourtRenderer> renderers;
};

inline CourtFixture make_court_fixture(const TennisCourtSpec& court) {
  CourtFixture f{make_court_rig(court, CourtRigOptions{}, kRigSeed), {}};
  for (const CourtCamera& camera : f.rig.cameras) f.renderers.emplace_back(camera, f.rig.court);
  return f;
}

/// The default court, with its net.
inline const CourtFixture& shared_court() {
  static const CourtFixture fixture = make_court_fixture(TennisCourtSpec{});
  return fixture;
}

/// The same rig (same cameras) on a court without a net.
inline const CourtFixture& shared_court_without_net() {
  static const CourtFixture fixture = [] {
    TennisCourtSpec court;
    court.net.enabled = false;
    return make_court_fixture(court);
  }();
  return fixture;
}

struct RenderedScene {
  CourtScene scene;
  std::vector<CourtRender> renders;  // one per camera
  std::vector<SphereTruth> truth;
};

inline RenderedScene render_in_all_cameras(const CourtFixture& court, const CourtScene& scene,
                                           std::uint64_t noise_seed = 0) {
  RenderedScene out{scene, {}, {}};
  for (const CourtRenderer& renderer : court.renderers) {
    out.renders.push_back(renderer.render(scene, noise_seed));
  }
  out.truth = court_scene_truth(court.rig, scene, out.renders);
  return out;
}

inline RenderedScene render_in_all_cameras(const CourtScene& scene, std::uint64_t noise_seed = 0) {
  return render_in_all_cameras(shared_court(), scene, noise_seed);
}

/// No noise, no shadow, no brightness change: a clean render for geometric checks.
inline CourtScenarioOptions clean_scenario() {
  CourtScenarioOptions options;
  options.noise_sigma = 0.0;
  options.brightness_gain = 1.0;
  options.shadow = false;
  return options;
}

}  // namespace ballsight::sim::test_support
