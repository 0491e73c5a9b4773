#pragma once
// Renders one camera's view of a court scene by ray casting: a floor pass for every pixel (court,
// lines, run-off, ground and sky; anti-aliased by the pixel's footprint on the ground), then the
// objects, ray-cast only inside their projected bounding boxes with 3x3 supersampling so that blob
// centroids are unbiased. Reports, per object, how much of it is visible and how much would be
// without occlusion: the visibility truth comes from the same rays as the image.
//
// The floor does not move, so its albedo, haze and ground point per pixel are computed once per
// camera with the ray table; a view then only lights the floor (sun, shadow band) and casts the
// objects. Measured in bench/sim_court.cpp (docs/sim-court.md).

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/ray_table.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

/// Supersamples (of 3x3 per pixel) of one object in a rendered view.
struct ObjectCoverage {
  int visible_samples = 0;     // where the object is the nearest surface
  int unoccluded_samples = 0;  // where the object is hit at all (occlusion ignored)

  /// visible / unoccluded, 0 when the object covers no sample.
  double visible_fraction() const;
};

struct CourtRender {
  cv::Mat bgr;         // CV_8UC3, after the scene's image effects
  cv::Mat object_ids;  // CV_32S: object seen at each pixel centre, -1 for floor and sky
  /// Per object: scene.spheres() in order, then the robot box (index spheres().size()).
  std::vector<ObjectCoverage> coverage;
};

class CourtRenderer {
 public:
  static constexpr int kSamplesPerAxis = 3;

  /// Precomputes the camera's ray table (a Newton solve per pixel) and the floor.
  CourtRenderer(const CourtCamera& camera, const TennisCourtSpec& court);

  const CourtCamera& camera() const { return camera_; }

  /// Renders the scene; `noise_seed` seeds the sensor noise of scene.effects.
  CourtRender render(const CourtScene& scene, std::uint64_t noise_seed) const;

 private:
  void precompute_floor(const TennisCourtSpec& court);
  void light_floor(const Lighting& lighting, cv::Mat& bgr) const;

  CourtCamera camera_;
  Vec3 center_in_field_;
  RayTable rays_;         // field frame
  cv::Mat floor_albedo_;  // CV_32FC3: floor albedo times (1 - haze); 0 for the sky
  cv::Mat floor_haze_;    // CV_32FC3: haze (or sky) colour added after lighting
  cv::Mat floor_point_;   // CV_32FC2: ground point x, y in the field frame
};

}  // namespace ballsight::sim
