#pragma once
// A non-central catadioptric rig, ray-traced: a pinhole camera (with radial lens distortion k1)
// looks up along the axis of a mirror of revolution above it (a sphere, a cone, or a free
// profile given as a table of height vs radius, the way MSL teams specify custom mirrors; each
// with an optional small surface ripple). A pixel's ray is reflected where it meets the mirror;
// a point is imaged where the one reflection in its azimuth plane sends the camera's ray to it.
// The image is flipped left-right, as omni robots display it, so that forward is up and the
// robot's right is right (docs/conventions.md). Frame: the rig's, origin at the camera's centre,
// z up the mirror's axis, x towards the top of the image.

#include <optional>
#include <string_view>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

enum class MirrorKind { kUnified, kSphere, kCone, kTable };

/// "unified", "sphere", "cone", "table".
std::string_view mirror_kind_name(MirrorKind kind);
/// The kind named `name`, or nullopt.
std::optional<MirrorKind> mirror_kind_named(std::string_view name);
/// The kind named `name`; throws InputError naming `where` and the choices otherwise.
MirrorKind parse_mirror_kind(std::string_view name, const std::string& where);

struct MirrorProfile {
  MirrorKind kind = MirrorKind::kUnified;
  double rim_radius_m = 0.04;         // the mirror's outer radius
  double apex_above_camera_m = 0.25;  // from the camera's centre to the mirror's lowest point
  double sphere_radius_m = 0.05;
  double cone_half_angle_deg = 50.0;  // between the axis and the surface
  /// Free profile: (radius, height above the apex) in metres, from radius 0, both increasing;
  /// monotone cubic between the points.
  std::vector<Vec2> table_m;
  double ripple_amplitude_m = 0.0;  // a sine in the height along the radius
  double ripple_period_m = 0.004;
  double lens_k1 = 0.0;  // radial distortion of the camera: x_d = x (1 + k1 |x|^2)

  bool operator==(const MirrorProfile&) const = default;

  /// Throws InputError naming the first invalid field (not used for kUnified).
  void validate() const;
};

/// The documented default mirror of each kind (docs/sim-omni.md): a sphere of 5 cm radius (on a
/// rig of use_mirror(), its radius-distance curve is cnc-msl's real one within 2.5 px and the
/// Tribots' within 5-7 %), a cone of 60 deg, and a compound free profile (a 5 cm sphere-like
/// centre, a more strongly curved outer ring from 2.4 cm: far range compressed harder than on the
/// real mirrors); each 4 cm in radius, its lowest point 25 cm above the camera.
MirrorProfile default_mirror(MirrorKind kind);

struct TracedRay {
  Vec3 origin;     // on the mirror (rig frame)
  Vec3 direction;  // unit, after the reflection
};

class MirrorTracer {
 public:
  /// A camera of `focal_px` whose principal point is `principal_px`.
  MirrorTracer(const MirrorProfile& profile, double focal_px, const Vec2& principal_px);

  /// The focal length that images the mirror's rim at `rim_px` from the principal point.
  static double focal_for_rim(const MirrorProfile& profile, double rim_px);

  /// Pixel -> reflected ray; nullopt when the pixel does not see the mirror.
  std::optional<TracedRay> trace(const Vec2& pixel) const;
  /// Point (rig frame) -> pixel; nullopt when no reflection on the mirror reaches it.
  std::optional<Vec2> project(const Vec3& point) const;

  /// The mirror's height above the apex and its slope at radius rho.
  double height(double rho) const;
  double slope(double rho) const;

 private:
  MirrorProfile profile_;
  double focal_px_;
  Vec2 principal_px_;
  std::vector<double> table_slopes_;  // kTable: the monotone cubic's slopes at the points
};

}  // namespace ballsight
