#pragma once
// Automatic calibration-marker matching: detected marker pixels in an omni image are matched to
// a known floor layout (markers on rays around the robot, as in the omnivision paper's Fig. 6),
// so a calibration needs no clicking.

#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct MarkerMatchOptions {
  Vec2 image_center{319.5, 239.5};
  double angle_tolerance_deg = 3.0;  // a tilted mirror bends bearings by a degree or two
  double radius_tolerance_px = 4.0;  // for rays with missing or extra detections
};

struct MarkerMatch {
  int layout_index = 0;  // index into the layout
  Vec2 pixel = Vec2::Zero();
};

/// Groups the layout into rays by bearing and the detections by image angle around a centre
/// refined from the innermost ring (robot bearing = image angle - 90 deg), then assigns along each
/// ray by increasing radius (the mapping is monotone). Rays whose detection count differs from
/// the layout, or whose radii disagree with their neighbours, are matched against the nearest
/// complete ray's radii; detections that fit nothing are dropped.
std::vector<MarkerMatch> match_markers_to_layout(const std::vector<Vec2>& marker_pixels,
                                                 const std::vector<Vec2>& layout_in_robot,
                                                 const MarkerMatchOptions& options = {});

}  // namespace ballsight
