#pragma once
// Multi-camera fusion: the observations of one object by several cameras become one object.
// Agglomerative: the pair of groups whose estimates are closest, measured by their expected errors
// (Mahalanobis distance), merges first, as long as it passes the gate and the two groups share no
// camera (a camera sees an object once, so two observations from one camera are two objects).
// A merged group's estimate is the information-weighted mean of its observations.

#include <Eigen/Core>
#include <vector>

#include "ballsight/world/field_observation.hpp"

namespace ballsight {

struct FusionOptions {
  /// Mahalanobis distance squared below which two groups may be one object: chi-square with two
  /// degrees of freedom, 13.8 = 99.9% of true pairs pass.
  double gate_chi2 = 13.8;
  /// Groups farther apart than this are never compared (bounds the search; not a gate).
  double search_radius_m = 1.0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct FusedObject {
  Vec2 position_m = Vec2::Zero();
  Eigen::Matrix2d covariance_m2 = Eigen::Matrix2d::Identity();
  std::vector<int> observations;  // indices into the input
  std::vector<int> cameras;       // cameras of those observations, ascending
};

/// Groups `observations` (any mix of cameras) into objects, in no particular order.
std::vector<FusedObject> fuse_observations(const std::vector<FieldObservation>& observations,
                                           const FusionOptions& options);

}  // namespace ballsight
