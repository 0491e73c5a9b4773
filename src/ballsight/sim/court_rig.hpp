#pragma once
// The four fixed cameras of the tennis-court set-up: IP cameras on poles at the corners of the
// run-off area, 4-6 m high, looking in over the court with a wide, barrel-distorted lens (the
// "four surveillance cameras" design of the tennis-ball-collecting-robot report, section 4.2).

#include <cstdint>
#include <vector>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight::sim {

/// One camera of the rig: its true intrinsics and its pose, OpenCV convention (x right, y down,
/// z forward).
struct CourtCamera {
  PinholeCamera camera;
  Rigid3 camera_from_field;

  Vec3 center_in_field() const { return camera_from_field.inverse().translation; }
};

/// Cameras of the rig: one per corner.
inline constexpr int kCourtRigCameras = 4;

/// The report's IP cameras: its printed image coordinates reach x = 1523. `sim court` and `eval
/// court` render at this size unless told otherwise.
inline constexpr int kReportCameraWidth = 1920;
inline constexpr int kReportCameraHeight = 1080;

struct CourtRigOptions {
  // The service's simulated court, the demo and the tests keep 1280 x 720: less than half the
  // pixels to render and detect per frame.
  int width = 1280;
  int height = 720;
  double hfov_deg = 90.0;  // horizontal field of view including the lens distortion
  /// Each camera's height, drawn in this range: a corner mast by default, down to a robot's
  /// camera a few decimetres above the court.
  double pole_height_min_m = 4.0;
  double pole_height_max_m = 6.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The court and its cameras: a fixed installation, shared by every scene rendered on it.
struct CourtRig {
  TennisCourtSpec court;
  std::vector<CourtCamera> cameras;
};

/// Four cameras, one per corner of the run-off area (order: +x+y, +x-y, -x-y, -x+y), with seeded
/// variations of pole position and height, aim, roll and intrinsics (k1 in [-0.35, -0.25], k2 in
/// [0.08, 0.12], k3 = 0, tangential terms below 1e-3). Deterministic for a seed.
CourtRig make_court_rig(const TennisCourtSpec& court, const CourtRigOptions& options,
                        std::uint64_t seed);

/// Pose of a camera at `eye` looking at `target` with the field's z axis up in the image, then
/// rolled by `roll_rad` about its optical axis.
Rigid3 camera_from_field_looking_at(const Vec3& eye, const Vec3& target, double roll_rad);

}  // namespace ballsight::sim
