#pragma once
// What a real omni calibration set's own measurements can show (issue 44's floor): each held-out
// sample predicted from its neighbours in the training samples with no model at all. Held-out
// directions: the nearest training direction on either side, each read at the sample's radius
// (linear along the ray between the samples that bracket it, or from the two nearest beyond
// them), then linear in angle between the two. A held-out whole distance: the sample's own
// direction read the same way along the ray. A model much below this floor would be fitting the
// measurements' noise, so the floor says how far below a baseline a model can honestly get.

#include <optional>
#include <span>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/held_out_folds.hpp"

namespace ballsight {

/// The neighbours' prediction of `sample`'s ground distance (cm) from `train` under `split`;
/// nullopt when the neighbours hold too few samples (fewer than two along a ray).
std::optional<double> neighbour_distance_cm(std::span<const PolarSample> train,
                                            const PolarSample& sample, HeldOutSplit split);

/// The floor of a set on the folds of `split` (the same folds the models are scored on): the
/// neighbours' absolute errors; a sample they cannot predict counts as its whole distance, as an
/// unmapped query of a model does. `unmapped` gets their count.
ErrorSummary neighbour_floor(std::span<const HeldOutFold> folds, HeldOutSplit split,
                             std::size_t& unmapped);

}  // namespace ballsight
