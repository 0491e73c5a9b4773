#include "ballsight/core/marker_layout.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

void MarkerLayout::validate() const {
  require(std::isfinite(bearing_step_deg) && bearing_step_deg >= 1.0 && bearing_step_deg <= 180.0,
          "marker layout.bearing_step_deg", "must be in [1, 180] deg");
  require(std::isfinite(min_distance_m) && min_distance_m >= 0.3, "marker layout.min_distance_m",
          "must be at least 0.3 m");
  require(
      std::isfinite(max_distance_m) && max_distance_m >= min_distance_m && max_distance_m <= 20.0,
      "marker layout.max_distance_m", "must be in [min_distance_m, 20] m");
  require(std::isfinite(distance_step_m) && distance_step_m >= 0.05,
          "marker layout.distance_step_m", "must be at least 0.05 m");
  require(std::isfinite(fill) && fill > 0.0 && fill < 1.0, "marker layout.fill",
          "must be in (0, 1)");
}

int MarkerLayout::rays() const {
  return static_cast<int>(std::floor(360.0 / bearing_step_deg + 1e-9));
}

int MarkerLayout::rings() const {
  return static_cast<int>(std::floor((max_distance_m - min_distance_m) / distance_step_m + 1e-9)) +
         1;
}

double calibration_marker_radius_m(double distance_m, const MarkerLayout& layout) {
  const double across_rays =
      2.0 * distance_m * std::sin(0.5 * rad_from_deg(layout.bearing_step_deg));
  const double along_ray = layout.distance_step_m;
  return 0.5 * layout.fill * std::min(across_rays, along_ray);
}

std::vector<LayoutMarker> layout_markers(const MarkerLayout& layout) {
  layout.validate();
  const int rays = layout.rays();
  const int rings = layout.rings();
  std::vector<LayoutMarker> markers;
  markers.reserve(static_cast<std::size_t>(rays) * rings);
  for (int ray = 0; ray < rays; ++ray) {
    for (int ring = 0; ring < rings; ++ring) {
      const double distance = layout.ring_distance_m(ring);
      markers.push_back({robot_point_from_bearing(ray * layout.bearing_step_deg, distance),
                         calibration_marker_radius_m(distance, layout)});
    }
  }
  return markers;
}

}  // namespace ballsight
