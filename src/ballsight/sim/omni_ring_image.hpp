#pragma once
// The ring image of calibration from one spin (detect/omni_rings.hpp), drawn with its truth: a
// robot turning on the spot over white floor lines sees each line's nearest points as a circle
// of the line's distance around it, so the image is that of concentric white bands of the
// lines' widths on the floor, seen through the omni rig (any mirror, a tilted camera, the mirror
// off the image centre), on a carpet with a texture of its own, with the robot's body in the
// middle and its struts as dark bars from the centre out. Each pixel is the mean of 4 x 4
// samples of the floor, so a band's edges are anti-aliased as a camera's are.

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

struct RingImageSpec {
  OmniRigParams rig;
  std::vector<double> distances_m{1.0, 1.5, 2.0, 2.5, 3.0};  // the lines' centres, increasing
  std::vector<double> line_widths_m{0.05};                   // per line, or one for all
  double robot_body_radius_m = 0.26;  // floor within it: the robot's dark body
  std::vector<double> strut_deg;      // image angles of the struts from the centre
  double strut_width_px = 6.0;        // 1 to 100
  double carpet_grey = 70.0;
  double line_grey = 215.0;
  // The carpet's texture: smooth blotches of two sizes (value noise at carpet_scale_m and a
  // quarter of it), up to +-carpet_texture grey levels, and tufts that brighten single samples.
  double carpet_texture = 0.0;
  double carpet_scale_m = 0.12;
  double noise_sigma = 3.0;  // sensor noise, grey levels
  std::uint64_t seed = 1;

  /// Line k's width: its own, or the one for all.
  double line_width_m(std::size_t k) const {
    return line_widths_m[std::min(k, line_widths_m.size() - 1)];
  }

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class RingImage {
 public:
  /// Draws the image; throws InputError for an invalid spec.
  explicit RingImage(const RingImageSpec& spec);

  const cv::Mat1b& grey() const { return grey_; }
  /// The principal point: where a user would put the rings' centre.
  Vec2 center() const { return rig_.principal_point(); }
  /// Where line k's centre (its distance) crosses the direction of image angle theta from
  /// center(); nullopt where the direction does not reach it inside the mirror.
  std::optional<double> true_radius_px(double theta_deg, std::size_t k) const;
  /// Whether a strut covers the direction at the radius, or comes within 1.5 px of it (a line
  /// there is partly hidden).
  bool strut_hides(double theta_deg, double radius_px) const;

 private:
  RingImageSpec spec_;
  OmniRig rig_;
  cv::Mat1b grey_;
};

}  // namespace ballsight::sim
