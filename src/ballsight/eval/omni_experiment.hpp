#pragma once
// The omnivision paper's experiment (Section V) on the simulator: a misaligned camera is
// calibrated by each method from clicked floor markers, then a ball at (400, 600) cm is located
// by a robot 120, 200 and 285 cm away turning in place in 30 degree steps. Methods: `poly` and
// `paper-mlp` (the paper's baseline and method, each with the paper's run-time pipeline),
// `ballsight`, `ballsight-auto` (ballsight calibrated from the markers it finds in a rendered
// calibration frame instead of clicks) and `oracle` (the simulator's true mapping with ballsight's
// detector: the floor).

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct OmniExperimentOptions {
  std::uint64_t seed = 1;
  double tilt_deg = 1.5;  // misalignment, as the paper's robot after a knock
  double tilt_azimuth_deg = 60.0;
  Vec2 center_offset_px{5.0, -3.0};          // mirror centre off the configured image centre
  MirrorKind mirror = MirrorKind::kUnified;  // the rig's mirror: its default_mirror()
  double sensor_noise = 3.0;                 // grey levels
  double click_noise_px = 1.0;               // marker clicks, per axis
  Vec2 ball_cm{400.0, 600.0};
  std::vector<int> distances_cm{120, 200, 285};
  double turn_step_deg = 30.0;
  /// When set, ballsight is also given the viewpoint height as measured on the robot: the true
  /// height plus a normal error of this standard deviation (drawn from the seed), weighed as such.
  std::optional<double> measured_height_sigma_cm;
  /// Which methods to run, of poly, paper-mlp, ballsight, ballsight-auto (ballsight calibrated
  /// without clicking, from one rendered calibration frame) and oracle (all by default).
  std::vector<std::string> methods{"poly", "paper-mlp", "ballsight", "ballsight-auto", "oracle"};

  /// Throws InputError naming the first invalid field.
  void validate() const;
  /// The misaligned rig these options describe.
  OmniRigParams rig_params() const;
};

struct DistanceResult {
  std::vector<std::optional<Vec2>> estimates_cm;  // one per robot heading; nullopt: not found
  double mean_error_cm = 0.0;                     // over the headings where the ball was found
  double std_x_cm = 0.0;                          // sample standard deviations, as the paper
  double std_y_cm = 0.0;
  int found = 0;
};

struct OmniMethodResult {
  std::map<int, DistanceResult> by_distance;
  double held_out_median_cm = 0.0;  // mapping error on random floor points (oracle: 0)
  double fit_seconds = 0.0;
  std::string calibration_error;  // why the method could not be calibrated (ballsight-auto)
};

struct OmniExperimentResult {
  OmniExperimentOptions options;
  std::map<std::string, OmniMethodResult> methods;  // poly, paper-mlp, ballsight, oracle
};

OmniExperimentResult run_omni_experiment(const OmniExperimentOptions& options);

/// {"methods": {"<method>": {"by_distance": {"120": {"mean_error_cm", "std_x_cm", "std_y_cm",
/// ...}}}}} plus the options.
nlohmann::json omni_experiment_json(const OmniExperimentResult& result);
/// An aligned text table, one row per method and distance.
std::string omni_experiment_table(const OmniExperimentResult& result);

}  // namespace ballsight
