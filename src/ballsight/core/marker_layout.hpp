#pragma once
// The calibration marker layout of the omnivision paper (Fig. 6, Table I): floor markers on rays
// around the robot every 10 deg, from 60 cm to 460 cm in 50 cm steps. The simulator lays them on
// its floor; calibration matches the markers it finds in an image to them.

#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct MarkerLayout {
  double bearing_step_deg = 10.0;  // rays at robot bearings 0, step, 2 step, ...
  double min_distance_m = 0.6;
  double max_distance_m = 4.6;
  double distance_step_m = 0.5;
  /// Marker diameter as a fraction of the distance to its nearest neighbour. With the default
  /// rig the rings beyond 4 m are ~5 px apart in the image, so this is a narrow window: 0.7 makes
  /// the far markers ~3.4 px thick with a ~1.6 px gap (0.72 can merge neighbours at half
  /// coverage, 0.67 leaves some 2 px thick; docs/sim-omni.md).
  double fill = 0.7;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  /// How many rays (every bearing_step_deg around) and rings (min_distance_m..max_distance_m
  /// every distance_step_m) the layout has.
  int rays() const;
  int rings() const;
  /// The distance of ring `ring` (0: the nearest), m.
  double ring_distance_m(int ring) const { return min_distance_m + ring * distance_step_m; }
};

/// Radius of a marker `distance_m` from the robot: grows with distance (neighbours on adjacent
/// rays spread apart) up to the spacing along a ray.
double calibration_marker_radius_m(double distance_m, const MarkerLayout& layout);

/// A marker of a layout: its centre in the robot frame (m) and its disc's radius (m, 0 when
/// unknown).
struct LayoutMarker {
  Vec2 p_in_robot = Vec2::Zero();
  double radius_m = 0.0;
};

/// The layout's markers around the robot. Ray-major: index = ray_index * rings + ring_index, ray
/// 0 straight ahead, counting counter-clockwise, ring 0 nearest. Throws InputError for an invalid
/// layout.
std::vector<LayoutMarker> layout_markers(const MarkerLayout& layout = {});

}  // namespace ballsight
