#pragma once
// Touching balls that every camera sees partly merged: a camera looking along a pair sees one
// blob, and a triangle of three is two blobs from almost every corner, so counting per image falls
// short and pairwise fusion cannot recover the missing ball. Here a group of nearby fused balls is
// refitted to all its cameras' observations at once, with the model that one observation may
// cover several balls (its centre is then their mean): the positions come from a weighted linear
// least-squares solve, the observation-to-ball assignment is re-estimated in turn, and a ball is
// added where that explains the observations much better (a chi-square drop), the balls staying
// at least about two radii apart.

#include <vector>

#include "ballsight/world/field_observation.hpp"
#include "ballsight/world/observation_fusion.hpp"

namespace ballsight {

struct ClusterOptions {
  double link_distance_radii = 4.0;  // fused balls this close (in ball radii) form a group
  double merged_sigma_radii = 0.35;  // extra error of an observation per further ball it covers
  // Balls a group's blobs amount to (most in one camera, m) -> count 1 + floor((m - offset) /
  // step): measured on the simulator's clusters (mutual hiding makes n balls look like ~0.7 n).
  double count_offset = 0.75;
  double count_step = 0.72;
  double assign_gate_chi2 = 25.0;      // an observation farther from a ball did not see it
  double min_chi2_gain = 4.0;          // a further ball must lower the chi-square this much
  double min_chi2_keep = 9.0;          // a ball whose removal raises the chi-square less goes
  double min_separation_radii = 1.75;  // balls closer than this cannot both be real
  int max_added = 2;                   // balls added to one group at most
  int iterations = 8;                  // assignment / solve rounds per hypothesis

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The fused balls after refitting every group of two or more nearby balls (and single balls whose
/// observations disagree); each result lists the observations assigned to it (an observation may
/// be listed by several balls).
std::vector<FusedObject> refine_clusters(const std::vector<FieldObservation>& observations,
                                         const std::vector<FusedObject>& fused,
                                         double ball_radius_m, const ClusterOptions& options);

}  // namespace ballsight
