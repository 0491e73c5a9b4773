#include "ballsight/sim/court_truth.hpp"

#include <cassert>

#include "ballsight/sim/silhouette.hpp"

namespace ballsight::sim {

SphereViewTruth sphere_view_truth(const CourtCamera& camera, const SceneSphere& sphere,
                                  const ObjectCoverage& coverage) {
  constexpr double kVisibleFraction = 0.5;
  constexpr double kNetFraction = 0.5;
  constexpr int kOutlineSamples = 96;
  SphereViewTruth view;
  const Vec3 c = camera.camera_from_field * sphere.center_in_field;
  view.center_px = camera.camera.project(c);
  if (const auto rim = sphere_outline_pixels(camera.camera, c, sphere.radius_m, kOutlineSamples)) {
    view.silhouette_centroid_px = polygon_centroid(*rim);
  }
  view.in_image = view.center_px && camera.camera.in_image(*view.center_px);
  view.visible_fraction = coverage.visible_fraction();
  view.visible = view.in_image && view.visible_fraction >= kVisibleFraction;
  view.hidden_by_net = view.in_image && coverage.net_fraction() >= kNetFraction;
  return view;
}

std::vector<SphereTruth> court_scene_truth(const CourtRig& rig, const CourtScene& scene,
                                           const std::vector<CourtRender>& renders) {
  assert(renders.size() == rig.cameras.size());
  std::vector<SphereTruth> truth;
  const std::vector<SceneSphere> spheres = scene.spheres();
  for (size_t i = 0; i < spheres.size(); ++i) {
    SphereTruth t{spheres[i], {}};
    for (size_t c = 0; c < rig.cameras.size(); ++c) {
      t.views.push_back(sphere_view_truth(rig.cameras[c], spheres[i], renders[c].coverage[i]));
    }
    truth.push_back(std::move(t));
  }
  return truth;
}

}  // namespace ballsight::sim
