#pragma once
// The blob centroid of a flat floor marker is the area centroid of the disc's image, which
// perspective (and the mirror) moves off the projection of the disc's centre: by up to about
// 0.2 px for the paper's layout, a shift every marker of a ring shares. Given a fitted floor
// model, the shift is predicted and removed, so automatically found markers become as unbiased
// as clicks on the centre (docs/omni-calibration.md).

#include <optional>
#include <span>
#include <vector>

#include "ballsight/calib/ballsight_model.hpp"
#include "ballsight/calib/marker_samples.hpp"

namespace ballsight {

/// A marker found in the image (its blob centroid), its disc's centre on the floor (robot frame,
/// m) and its radius (m).
struct FoundDisc {
  Vec2 centroid_px = Vec2::Zero();
  Vec2 p_in_robot = Vec2::Zero();
  double radius_m = 0.0;
};

/// Area centroid of the disc's image minus the projection of its centre, under `params` (the
/// distortion terms are ignored); nullopt when part of the disc does not project.
std::optional<Vec2> disc_centroid_offset_px(const CatadioptricFloorParams& params,
                                            const Vec2& center_cm, double radius_cm);

/// The discs as marker observations at their centres' estimated pixels: centroid minus the
/// predicted offset (the centroid itself where the offset is undefined).
std::vector<MarkerObservation> disc_centres(std::span<const FoundDisc> discs,
                                            const CatadioptricFloorParams& params);

/// Samples from the discs' centroids, fitted with ballsight's model, the centroid offsets that
/// model predicts removed, `iterations` times. Throws InputError as fit_ballsight_model.
std::vector<PolarSample> debiased_disc_samples(std::span<const FoundDisc> discs,
                                               const OmniImage& image, int iterations = 2);

}  // namespace ballsight
