#pragma once
// The true pixel -> ground mapping of an omni rig baked into a ground map: the simulator's truth
// as a lookup table, for oracles, benchmarks and tests.

#include "ballsight/camera/ground_map.hpp"
#include "ballsight/camera/omni_rig.hpp"

namespace ballsight {

/// `info` gives the image size, centre and valid range; the viewpoint height is the rig's.
inline GroundMap ground_map_from_rig(const OmniRig& rig, GroundMapInfo info) {
  info.viewpoint_height_cm = rig.viewpoint_height_m() * 100.0;
  return build_ground_map(
      [&rig](const Vec2& pixel) -> std::optional<Vec2> {
        const std::optional<Vec2> p_m = rig.ground_from_pixel(pixel);
        if (!p_m) return std::nullopt;
        return 100.0 * *p_m;
      },
      info);
}

}  // namespace ballsight
