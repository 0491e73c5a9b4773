#pragma once
// The omni methods on real calibration data of other teams (../shared/data/real/omni and the
// omnivision paper's Table I): each method is fitted on part of a set and scored on the rest,
// by the two splits of calib/held_out_folds.hpp (held-out directions, a held-out whole
// distance, at most `max_distance_folds` of them). The error is that of the ground distance (real
// sets carry no bearings); a query a model cannot map counts as an error of its whole distance.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/calib/ground_error.hpp"
#include "ballsight/calib/held_out_folds.hpp"
#include "ballsight/calib/omni_ground_model.hpp"

namespace ballsight {

/// One real calibration set as polar samples around its image centre.
struct RealOmniSet {
  std::string name;  // "tribots-2005", "cnc-msl-nase-2016-03", "minhoteam-profile-4", "table-1"
  std::vector<PolarSample> samples;
  OmniImage image;
};

/// The sets found under `data_dir` (the shared data folder); `missing` gets the files of the
/// sets that are absent. Throws InputError when a present file is malformed.
std::vector<RealOmniSet> load_real_omni_sets(const std::filesystem::path& data_dir,
                                             std::vector<std::string>& missing);

/// One method on one split of one set.
struct HeldOutScore {
  std::string method;
  HeldOutSplit split = HeldOutSplit::kDirections;
  ErrorSummary distance_cm;
  std::size_t unmapped = 0;  // held-out samples the model could not map (counted as errors)
  double fit_seconds = 0.0;  // all the folds' fits
};

struct RealOmniSetResult {
  std::string name;
  std::size_t samples = 0;
  std::size_t directions = 0;
  std::vector<double> distances_cm;
  std::vector<HeldOutScore> scores;  // per split, per method; no direction split with one direction
  /// Per split, on the same folds: the set's neighbours' prediction (eval/omni_data_floor.hpp),
  /// as method "floor" (fit_seconds 0).
  std::vector<HeldOutScore> floors;

  /// The score of `method` on `split`, or nullptr.
  const HeldOutScore* find(std::string_view method, HeldOutSplit split) const;
};

struct OmniRealOptions {
  std::filesystem::path data_dir = "../shared/data";  // the shared data folder
  std::vector<std::string> methods{"poly", "paper-mlp", "ballsight"};
  /// Held-out whole distances per set at most, evenly spread (MinhoTeam's profiles have 22
  /// interior distances; paper-mlp takes about a minute a fit).
  std::size_t max_distance_folds = 5;
  int jobs = 2;  // fits run at once
  /// Called (from any thread, one at a time) with a line of progress after each score.
  std::function<void(const std::string&)> progress;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct OmniRealResult {
  std::vector<RealOmniSetResult> sets;
  std::vector<std::string> missing;
};

OmniRealResult run_omni_real(const OmniRealOptions& options);

/// Which of issue 44's rules bounds ballsight's median on a split: 0.7x the better baseline
/// where the floor lies below that; else 1.1x the floor where that is below the better baseline;
/// else the better baseline itself.
enum class OmniRealRule { seven_tenths, floor, better_baseline };
std::string_view omni_real_rule_name(OmniRealRule rule);

/// Issue 44's target on one split, where poly, paper-mlp and ballsight all ran.
struct OmniRealTarget {
  double better_baseline_cm = 0.0;
  double floor_cm = 0.0;
  double ballsight_cm = 0.0;
  OmniRealRule rule = OmniRealRule::better_baseline;
  double limit_cm = 0.0;  // the rule's bound
  bool met() const { return ballsight_cm <= limit_cm; }
};
std::optional<OmniRealTarget> omni_real_target(const RealOmniSetResult& set, HeldOutSplit split);

/// {"sets": [{"name", "samples", "directions", "distances_cm", "scores": [{"method", "split",
/// "median_cm", "mean_cm", "p95_cm", "max_cm", "count", "unmapped", "fit_seconds"}],
/// "floor": [the same for method "floor"], "ballsight_over_best_baseline": {"directions": r,
/// "distance": r}, "targets": {split: {"better_baseline_cm", "floor_cm", "ballsight_cm",
/// "limit_cm", "rule", "met"}}}], "missing": [...]}.
nlohmann::json omni_real_json(const OmniRealResult& result);
/// An aligned text table, one row per set, split and method (the floor's too), then per split the
/// target where it can be judged.
std::string omni_real_table(const OmniRealResult& result);

}  // namespace ballsight
