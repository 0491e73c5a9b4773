#pragma once
// `eval court`: both court methods (the report's pipeline and ballsight's) on simulated scenes of
// the tennis court, each calibrated from rendered chessboards and reference balls, scored against
// the simulator's truth (court_metrics.hpp; definitions in docs/court-eval.md).

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/eval/court_eval_calibration.hpp"
#include "ballsight/eval/court_metrics.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight {

struct CourtEvalOptions {
  std::uint64_t seed = 1;
  int scenes = 10;
  sim::TennisCourtSpec court;  // with its net unless court.net.enabled is false
  sim::CourtRigOptions rig;
  sim::CourtScenarioOptions scenario;  // 20-60 balls, clusters, balls by the robot, shadow, noise
  int chessboard_views = 15;           // per camera, for the intrinsics
  double match_radius_m = 0.10;
  std::optional<std::filesystem::path> plot_dir;  // pictures of the first plot_scenes scenes
  int plot_scenes = 2;
  bool plot_mistakes = false;  // also pictures of every scene where ballsight got a ball wrong

  static constexpr int kMaxScenes = 1000;
  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct MethodReport {
  CourtMethod method = CourtMethod::ballsight;
  CourtScores scores;
  EvalCalibration calibration;
  std::string calibration_error;     // why the method could not be calibrated ("" when it was)
  std::vector<double> frame_set_ms;  // wall time of one frame set -> world model, per scene
  /// The scores of the scenes of each light condition (sim::light_condition_name).
  std::map<std::string, CourtScores> by_condition;
};

struct CourtEvalReport {
  CourtEvalOptions options;
  std::vector<MethodReport> methods;  // seed, then ballsight
  std::vector<std::string> pictures;  // files written into plot_dir
};

/// On the scenes of CourtEvalScenes (court_eval_scenes.hpp) with options.seed.
CourtEvalReport run_court_eval(const CourtEvalOptions& options);

/// {"methods": {"seed": {...}, "ballsight": {...}}, ...}: recall, precision, duplicates,
/// ball_error_mean_cm, ball_error_p95_cm, robot_position_error_cm, robot_heading_error_deg and
/// more per method.
nlohmann::json court_eval_json(const CourtEvalReport& report);

/// A table for people.
std::string court_eval_text(const CourtEvalReport& report);

}  // namespace ballsight
