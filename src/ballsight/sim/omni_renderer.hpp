#pragma once
// Renders an omni scene by casting each pixel's ray from the rig's single effective viewpoint:
// the rays (and their floor hits in the robot frame) are computed once per rig; a frame then
// shades the floor for every pixel (one sample per pixel) and ray-casts only the pixels inside
// each object's image bounding box, 4x4 samples per pixel, so that object edges are anti-aliased
// (pixel colour = the covered fraction's colour blended over the floor). Pixels outside the
// mirror circle are black.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/sim/omni_scene.hpp"
#include "ballsight/sim/omni_truth.hpp"

namespace ballsight::sim {

struct OmniFrame {
  cv::Mat bgr;  // CV_8UC3, rig.width x rig.height
  OmniTruth truth;
};

class OmniRenderer {
 public:
  /// Precomputes the per-pixel rays of the rig; throws InputError for invalid parameters.
  explicit OmniRenderer(const OmniRigParams& rig_params);

  const OmniRig& rig() const { return rig_; }

  /// Renders `scene`, whose rig must be this renderer's; throws InputError for an invalid scene
  /// or a different rig.
  OmniFrame render(const OmniScene& scene) const;

 private:
  // Ordered: a kind has everything the kinds before it have (a ray, then also a floor hit).
  enum class PixelKind : std::uint8_t { kOutsideMirror, kAboveHorizon, kFloor };

  /// A per-pixel quantity near a pixel centre to first order: value + dx * d_dx + dy * d_dy for
  /// sub-pixel offsets (dx, dy).
  template <class V>
  struct Local {
    V value, d_dx, d_dy;
    V at(double dx, double dy) const { return value + dx * d_dx + dy * d_dy; }
  };

  void shade_floor(const OmniScene& scene, const MslField& field, cv::Mat& bgr) const;
  void draw_marker(const OmniScene& scene, const FloorMarker& marker, cv::Mat& bgr) const;
  void draw_ball(const OmniScene& scene, cv::Mat& bgr) const;
  /// Pixel rectangle around the image of robot-frame outline points, clipped to the image.
  cv::Rect image_box(const std::vector<Vec3>& outline_in_robot) const;
  /// `values` around pixel (x, y) from differences with the neighbours of kind >= `least`.
  template <class V>
  Local<V> local(const std::vector<V>& values, int x, int y, PixelKind least) const;

  OmniRig rig_;
  std::vector<PixelKind> kind_;  // row-major, one per pixel
  std::vector<Vec3> ray_;        // unit ray in the robot frame (not for kOutsideMirror)
  std::vector<Vec3> origin_;     // where it starts: the viewpoint, or the traced mirror's point
  std::vector<Vec2> floor_;      // floor hit in the robot frame (kFloor only)
};

/// One-off convenience: builds a renderer for scene.rig and renders the scene.
OmniFrame render_omni_scene(const OmniScene& scene);

}  // namespace ballsight::sim
