#pragma once
// An omnidirectional camera on a robot: a central catadioptric model (camera + mirror as one
// unified camera) looking down at the floor from its effective viewpoint, or a ray-traced
// camera and mirror of another profile (camera/mirror_tracer.hpp: non-central), mounted with a
// height, a small tilt and an image-centre offset, the misalignments the omnivision paper
// corrects.

#include <optional>

#include "ballsight/camera/mirror_tracer.hpp"
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
  /// The mirror: the unified model (xi, focal_px and height_m: the effective viewpoint's), or a
  /// traced profile (height_m: the camera's centre; its focal length images the rim at
  /// mirror_radius_px; xi and focal_px unused).
  MirrorProfile mirror;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The rig with `kind`'s default_mirror(); a traced mirror's camera at 0.9 m (the mirror's lowest
/// point 1.15 m above the floor).
OmniRigParams with_mirror(OmniRigParams params, MirrorKind kind);

class OmniRig {
 public:
  explicit OmniRig(const OmniRigParams& params = {});

  const OmniRigParams& params() const { return params_; }
  const UnifiedCamera& camera() const { return camera_; }
  const Rigid3& robot_from_camera() const { return robot_from_camera_; }
  /// Where the mirror's image is centred (the principal point).
  Vec2 principal_point() const;

  /// Pixel -> the ray it sees, robot frame (for the unified model from its viewpoint,
  /// robot_from_camera().translation); nullopt outside the mirror's image.
  std::optional<TracedRay> viewing_ray(const Vec2& pixel) const;
  /// Where the rays that see `p_in_robot` come from: the unified model's viewpoint, or the point
  /// of a traced mirror that reflects it (the viewpoint when nothing does).
  Vec3 viewpoint_towards(const Vec3& p_in_robot) const;
  /// The height of the viewpoint that sees the floor 1.5 m ahead (the unified model's own).
  double viewpoint_height_m() const { return viewpoint_towards({1.5, 0.0, 0.0}).z(); }
  /// Point in the robot frame -> pixel, also outside the mirror's image; nullopt when the model
  /// does not image it.
  std::optional<Vec2> project(const Vec3& p_in_robot) const;
  /// Pixel -> ground point (z = 0) in the robot frame, metres; nullopt above the horizon.
  std::optional<Vec2> ground_from_pixel(const Vec2& pixel) const;
  /// Point in the robot frame -> pixel; nullopt when not imaged inside the mirror.
  std::optional<Vec2> pixel_from_point(const Vec3& p_in_robot) const;

 private:
  OmniRigParams params_;
  UnifiedCamera camera_;
  Rigid3 robot_from_camera_;
  std::optional<MirrorTracer> tracer_;  // traced mirrors
  Rigid3 robot_from_mirror_;            // traced mirrors: the rig frame (camera/mirror_tracer.hpp)
};

}  // namespace ballsight
