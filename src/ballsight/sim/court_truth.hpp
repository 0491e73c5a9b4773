#pragma once
// Ground truth of a rendered court scene, per object and camera: where the object's centre
// projects, where the centroid of its outline is (analytic, independent of the renderer), whether
// it is in the image, how much of it the renderer showed unoccluded and whether the net hides it.

#include <optional>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scene.hpp"

namespace ballsight::sim {

struct SphereViewTruth {
  std::optional<Vec2> center_px;               // projection of the sphere's centre
  std::optional<Vec2> silhouette_centroid_px;  // centroid of the projected outline
  bool in_image = false;                       // the centre projects inside the image
  double visible_fraction = 0.0;               // ObjectCoverage::visible_fraction()
  bool visible = false;                        // in_image and visible_fraction >= 0.5
  bool hidden_by_net = false;                  // in_image and ObjectCoverage::net_fraction() >= 0.5
};

struct SphereTruth {
  SceneSphere sphere;
  std::vector<SphereViewTruth> views;  // one per camera of the rig
};

/// One camera's truth for one sphere; `coverage` is the sphere's entry in the camera's render.
SphereViewTruth sphere_view_truth(const CourtCamera& camera, const SceneSphere& sphere,
                                  const ObjectCoverage& coverage);

/// Truth for every sphere of the scene (scene.spheres() order); `renders[i]` is camera i's view.
std::vector<SphereTruth> court_scene_truth(const CourtRig& rig, const CourtScene& scene,
                                           const std::vector<CourtRender>& renders);

}  // namespace ballsight::sim
