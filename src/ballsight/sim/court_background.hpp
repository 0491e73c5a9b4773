#pragma once
// What does not move in a court camera's view: the floor (court, lines, run-off, ground), the sky
// and the net. Computed once per camera from its ray table, then lit per view (sun, shadow band).
// The floor is anti-aliased by each pixel's footprint on the ground; the net and its posts by
// 3x3 supersampling, as the objects are (court_renderer.hpp), and a sample that hits the net
// shows the net, not the floor behind it.

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/ray_table.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "ballsight/sim/tennis_net.hpp"

namespace ballsight::sim {

/// Aerial perspective: what is seen at distance `t_m` is mixed with kSkyHorizonBgr by this share
/// (applied to the floor and the net; the renderer applies none to the objects).
float haze_share(double t_m);
inline const cv::Vec3f kSkyHorizonBgr{225.0f, 215.0f, 205.0f};

class CourtBackground {
 public:
  /// `rays` are the camera's rays in the field frame, `samples_per_axis` the supersampling of the
  /// net. Throws InputError when `court` is invalid.
  CourtBackground(const CourtCamera& camera, const RayTable& rays, const TennisCourtSpec& court,
                  int samples_per_axis);

  /// Writes the background lit by `lighting`, with `leaves` on the floor, into `bgr` (CV_8UC3,
  /// the camera's image size). A pixel takes a leaf's colour where its ground point lies in it.
  void light(const Lighting& lighting, const std::vector<FloorLeaf>& leaves, cv::Mat& bgr) const;

  /// Distance from the camera centre along the unit ray `direction` to the net or a post;
  /// infinity when the ray misses them or the court has no net.
  double net_distance(const Vec3& direction) const;

 private:
  /// A pixel where some of the supersamples hit the net.
  struct NetPixel {
    int x = 0, y = 0;
    float floor_share = 0.0f;  // of the samples, those that see past the net (floor or sky)
    cv::Vec3f albedo;          // the net samples' albedo x (1 - haze), summed, over all samples
    cv::Vec3f haze;            // their haze, likewise
    Vec3 normal_in_field;      // mean normal of the net samples
    Vec3 point_in_field;       // mean point hit
  };

  void precompute_floor(const RayTable& rays, const TennisCourtSpec& court);
  void precompute_net(const CourtCamera& camera, const RayTable& rays, int samples_per_axis);

  Vec3 center_in_field_;
  std::optional<TennisNet> net_;
  cv::Mat floor_albedo_;  // CV_32FC3: floor albedo times (1 - haze); 0 for the sky
  cv::Mat floor_haze_;    // CV_32FC3: haze (or sky) colour added after lighting
  cv::Mat floor_point_;   // CV_32FC2: ground point x, y in the field frame
  std::vector<NetPixel> net_pixels_;
};

}  // namespace ballsight::sim
