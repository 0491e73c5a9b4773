#pragma once
// Renders one camera's view of a court scene by ray casting: the background (floor, lines, run-off,
// ground, sky and the net; court_background.hpp) for every pixel, then the objects, ray-cast only
// inside their projected bounding boxes with 3x3 supersampling so that blob centroids are unbiased.
// Reports, per object, how much of it is visible and how much would be without occlusion (by other
// objects or the net): the visibility truth comes from the same rays as the image.
//
// The background does not move, so it is computed once per camera with the ray table; a view then
// only lights it (sun, shadow band) and casts the objects, each sample ray also against the net so
// that it hides what is behind it. Measured in bench/sim_court.cpp (docs/sim-court.md).

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/sim/court_background.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/ray_table.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

/// Supersamples (of 3x3 per pixel) of one object in a rendered view.
struct ObjectCoverage {
  int visible_samples = 0;     // where the object is the nearest surface
  int unoccluded_samples = 0;  // where the object is hit at all (occlusion ignored)
  int net_samples = 0;         // where the object is hit but the net or a post is nearer

  /// visible / unoccluded, 0 when the object covers no sample.
  double visible_fraction() const;
  /// net / unoccluded, 0 when the object covers no sample.
  double net_fraction() const;
};

struct CourtRender {
  cv::Mat bgr;         // CV_8UC3, after the scene's image effects
  cv::Mat object_ids;  // CV_32S: object seen at each pixel centre, -1 for the background
  /// Per object: scene.spheres() in order, then the robot box (index spheres().size()), then
  /// scene.bottles in order, then scene.obstacles in order.
  std::vector<ObjectCoverage> coverage;
};

class CourtRenderer {
 public:
  static constexpr int kSamplesPerAxis = 3;

  /// Precomputes the camera's ray table (a Newton solve per pixel) and the background.
  CourtRenderer(const CourtCamera& camera, const TennisCourtSpec& court);

  const CourtCamera& camera() const { return camera_; }

  /// Renders the scene; `noise_seed` seeds the sensor noise of scene.effects.
  CourtRender render(const CourtScene& scene, std::uint64_t noise_seed) const;
  /// The same from the background already lit by scene.lighting with scene.leaves
  /// (lit_background): a sequence of views under one sun lights it once.
  CourtRender render(const CourtScene& scene, std::uint64_t noise_seed,
                     const cv::Mat& lit_background) const;
  /// The background under `lighting` with `leaves` on the floor (CV_8UC3, the camera's image
  /// size).
  cv::Mat lit_background(const Lighting& lighting, const std::vector<FloorLeaf>& leaves) const;

 private:
  CourtCamera camera_;
  Vec3 center_in_field_;
  RayTable rays_;  // field frame
  CourtBackground background_;
};

}  // namespace ballsight::sim
