#pragma once
// An omnidirectional camera on a robot: a central catadioptric model (camera + mirror as one
// unified camera) looking down at the floor from its effective viewpoint, mounted with a height,
// a small tilt and an image-centre offset, the misalignments the omnivision paper corrects.

#include <optional>

#include "ballsight/camera/unified.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// How the rig is built and how it is misaligned. Defaults give a ground-distance vs
/// pixel-radius profile close to Table I of the omnivision paper (60 cm ~ 81 px, 260 cm ~ 172 px)
/// with a mirror image 480 px across in a 640x480 frame.
struct OmniRigParams {
  int width = 640;
  int height = 480;
  double xi = 0.5;
  double focal_px = 128.0;
  double height_m = 0.6;                 // effective viewpoint above the floor
  double tilt_deg = 0.0;                 // mirror/camera axis tilt away from vertical
  double tilt_azimuth_deg = 0.0;         // robot bearing towards which the axis tilts
  Vec2 center_offset_px = Vec2::Zero();  // principal point offset from the image centre
  double mirror_radius_px = 240.0;       // radius of the mirror's image around the principal point

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class OmniRig {
 public:
  explicit OmniRig(const OmniRigParams& params = {});

  const OmniRigParams& params() const { return params_; }
  const UnifiedCamera& camera() const { return camera_; }
  const Rigid3& robot_from_camera() const { return robot_from_camera_; }
  /// Where the mirror's image is centred (the principal point).
  Vec2 principal_point() const;

  /// Pixel -> unit ray in the robot frame (origin robot_from_camera().translation); nullopt
  /// outside the mirror's image.
  std::optional<Vec3> ray_in_robot(const Vec2& pixel) const;
  /// Pixel -> ground point (z = 0) in the robot frame, metres; nullopt above the horizon.
  std::optional<Vec2> ground_from_pixel(const Vec2& pixel) const;
  /// Point in the robot frame -> pixel; nullopt when not imaged inside the mirror.
  std::optional<Vec2> pixel_from_point(const Vec3& p_in_robot) const;

 private:
  OmniRigParams params_;
  UnifiedCamera camera_;
  Rigid3 robot_from_camera_;
};

}  // namespace ballsight
