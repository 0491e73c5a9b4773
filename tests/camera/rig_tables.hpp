#pragma once
// Tables built from the true mapping of a misaligned omnidirectional rig, for table tests.

#include <optional>

#include "ballsight/camera/ground_map.hpp"
#include "ballsight/camera/omni_rig.hpp"

namespace ballsight::test {

/// 2 deg tilt and a 5 px principal point offset: the misalignments the paper calibrates away.
inline OmniRigParams misaligned_rig_params() {
  OmniRigParams params;
  params.tilt_deg = 2.0;
  params.tilt_azimuth_deg = 30.0;
  params.center_offset_px = {3.0, 4.0};
  return params;
}

/// OmniRig::ground_from_pixel in cm.
inline PixelToGroundCm true_ground_cm(const OmniRig& rig) {
  return [&rig](const Vec2& pixel) -> std::optional<Vec2> {
    const std::optional<Vec2> p_m = rig.ground_from_pixel(pixel);
    if (!p_m) return std::nullopt;
    return 100.0 * *p_m;
  };
}

/// Around the nominal image centre (not the offset principal point), out to ~6.5 m.
inline GroundMapInfo rig_table_info() {
  GroundMapInfo info;
  info.width = 640;
  info.height = 480;
  info.image_center_px = {319.5, 239.5};
  info.min_radius_px = 30.0;
  info.max_radius_px = 200.0;
  info.method = "omni-rig-truth";
  return info;
}

}  // namespace ballsight::test
