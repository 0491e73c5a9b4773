#pragma once
// Touching balls that every camera sees partly merged: a camera looking along a pair sees one
// blob, and a triangle of three is two blobs from almost every corner, so counting per image falls
// short and pairwise fusion cannot recover the missing ball. Here a group of nearby fused balls is
// refitted to all its cameras' observations at once, with the model that one observation may
// cover several balls (its centre is then their mean): the positions come from a weighted linear
// least-squares solve, the observation-to-ball assignment is re-estimated in turn, and a ball is
// added where that explains the observations much better (a chi-square drop), the balls staying
// at least about two radii apart.

#include <functional>
#include <vector>

#include "ballsight/world/field_observation.hpp"
#include "ballsight/world/observation_fusion.hpp"

namespace ballsight {

struct ClusterOptions {
  double link_distance_radii = 4.0;  // fused balls this close (in ball radii) form a group
  double merged_sigma_radii = 0.35;  // extra error of an observation per further ball it covers
  // The balls' images must add up to the size each camera measured: chi-square with an error of
  // floor + share x balls (the detector's size of one ball spreads by ~15%).
  double size_sigma_floor = 0.1;
  double size_sigma_share = 0.12;
  double blur_px = 0.15;               // the detector's blur of a ball's image (its size model)
  double assign_gate_chi2 = 25.0;      // an observation farther from a ball did not see it
  double min_chi2_gain = 4.0;          // a further ball must lower the chi-square this much
  double min_chi2_keep = 9.0;          // a ball whose removal raises the chi-square less goes
  double min_separation_radii = 1.75;  // balls closer than this cannot both be real
  int max_added = 2;                   // balls added to one group at most
  int iterations = 3;                  // assignment / solve rounds per hypothesis

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Smallest distance between two of `balls` (the largest double for fewer than two).
double min_separation(const std::vector<Vec2>& balls);

/// Indices of `fused` grouped by links shorter than `link_m` (transitively), in no particular
/// order.
std::vector<std::vector<int>> ball_groups(const std::vector<FusedObject>& fused, double link_m);

/// Indices 0..count-1 grouped by `linked(i, j)` (i < j, transitively), in no particular order.
std::vector<std::vector<int>> linked_groups(size_t count,
                                            const std::function<bool(size_t, size_t)>& linked);

/// `fit(group)` of every group side by side on the machine's cores (oneTBB's pool: OpenCV's may
/// be kept to one thread by a caller doing image work), the results joined in the groups' order.
/// `fit` must be safe to call from several threads at once.
std::vector<FusedObject> fit_groups_in_parallel(
    const std::vector<std::vector<int>>& groups,
    const std::function<std::vector<FusedObject>(const std::vector<int>& group)>& fit);

/// The fused balls after refitting every group of two or more nearby balls (and single balls whose
/// observations disagree); each result lists the observations assigned to it (an observation may
/// be listed by several balls).
std::vector<FusedObject> refine_clusters(const std::vector<FieldObservation>& observations,
                                         const std::vector<FusedObject>& fused,
                                         double ball_radius_m, const ClusterOptions& options);

}  // namespace ballsight
