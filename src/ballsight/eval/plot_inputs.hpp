#pragma once
// What the pictures of viz/ draw, read from the values of the experiments and the simulator that
// viz may not see: the simulator's court, a closed loop's record, a table's inspection, the court
// evaluation's truth and mistakes, the omni experiment's estimates.

#include <vector>

#include "ballsight/calib/lut_inspect.hpp"
#include "ballsight/eval/court_metrics.hpp"
#include "ballsight/eval/omni_experiment.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "ballsight/sim/tennis_court.hpp"
#include "ballsight/viz/court_map.hpp"
#include "ballsight/viz/court_plots.hpp"
#include "ballsight/viz/estimate_plot.hpp"
#include "ballsight/viz/loop_plot.hpp"
#include "ballsight/viz/lut_plot.hpp"

namespace ballsight {

/// The court's floor, lines and net (when it has one) in its colours.
CourtFloor court_floor(const sim::TennisCourtSpec& court);

/// The robot's true path, the routes published, when each ball was collected.
LoopMapInput loop_map_input(const LoopTruth& truth);

/// The table's rays in kLutFigureDirectionsDeg, its heat map and the inspection's findings.
LutFigureInput lut_figure_input(const InspectedLut& lut, const LutInspection& inspection);

std::vector<TrueBallMark> true_ball_marks(const std::vector<TruthBall>& truth);
/// Each mistake with the first letter of its kind (mistake_kind_name): M, D or F.
std::vector<MistakeMark> mistake_marks(const std::vector<BallMistake>& mistakes);

/// One layer per calibrated method, in the result's order, in the method's colour.
std::vector<EstimateLayer> estimate_layers(const OmniExperimentResult& result);

}  // namespace ballsight
