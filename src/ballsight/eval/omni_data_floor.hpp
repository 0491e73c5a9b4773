#pragma once
// A reference from a real omni calibration set itself (issue 44's floor): each held-out sample
// predicted from its neighbours in the training samples with no model at all. Held-out
// directions: the nearest training direction on either side, each read at the sample's radius
// (linear along the ray between the samples that bracket it, or through the two nearest beyond
// them), then linear in angle between the two; where one side has no direction, or its nearest
// ray fewer than two radii, the other side's ray is read alone. A held-out whole distance: the
// sample's own direction read the same way along the ray. The floor holds the neighbours' and the
// sample's measurement errors and the interpolation's bias, so a model can beat it; where it is
// low, though, a model far below the baselines is not needed to reach it (issue 44's target).

#include <optional>
#include <span>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/held_out_folds.hpp"

namespace ballsight {

/// The neighbours' prediction of `sample`'s ground distance (cm) from `train` under `split`;
/// nullopt when no ray they would read holds two radii.
std::optional<double> neighbour_distance_cm(std::span<const PolarSample> train,
                                            const PolarSample& sample, HeldOutSplit split);

/// A held-out sample's error (cm): that of `predicted_cm`, or, when there is no prediction, the
/// sample's whole distance (counted in `unmapped`): how a model's unmapped query counts too.
double held_out_error_cm(const std::optional<double>& predicted_cm, const PolarSample& sample,
                         std::size_t& unmapped);

/// The floor on `folds` (the folds the models are scored on) of `split`.
ErrorSummary neighbour_floor(std::span<const HeldOutFold> folds, HeldOutSplit split,
                             std::size_t& unmapped);

}  // namespace ballsight
