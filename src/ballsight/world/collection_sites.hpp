#pragma once
// Collection sites: balls close enough to be swept up in one pass of the robot's collector (the
// tennis-ball-collecting-robot report, section 7.8: its collector is 70 cm wide, so nearby balls
// are aggregated). Here a site keeps its individual balls, and every ball of a site lies within
// the collector width of every other (complete linkage), so that a site never strings a chain of
// balls along the court.

#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct CollectionSite {
  Vec2 center_m = Vec2::Zero();  // mean of its balls
  std::vector<int> balls;        // indices into the balls given, ascending
  double diameter_m = 0.0;       // largest distance between two of its balls
};

/// Groups `balls` (field positions) into sites no wider than `collector_width_m`: the two sites
/// whose union is narrowest merge first while it fits. Sites are ordered by their first ball.
std::vector<CollectionSite> collection_sites(const std::vector<Vec2>& balls,
                                             double collector_width_m);

}  // namespace ballsight
