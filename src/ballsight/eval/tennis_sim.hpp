#pragma once
// `eval tennis-sim`: the camera-free ball detectors of `eval detect-real` (ballsight's, the
// tennis report's HSV one) on the court simulator's camera frames, labelled from its truth like
// the real photos: the box around the outline of every tennis ball the frame shows (its centre in
// the image, half of it or more unhidden) at `min_radius_px` or more. A detection on any other
// sphere (a smaller or hidden ball, one whose centre lies outside the image, a reference ball, a
// robot marker) is neither right nor wrong: it is left out before the matching. Figures per light
// condition of the scenes (sun, hard shadow, overcast, indoor) and by the balls' radius. A seed
// gives the scenes of `eval court` with that seed (court_eval_scenes.hpp).

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ballsight/detect/ball_labels.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight {

struct TennisSimOptions {
  std::uint64_t seed = 1;
  int scenes = 10;
  sim::TennisCourtSpec court;
  sim::CourtRigOptions rig;  // the simulator's 1280 x 720 unless told otherwise
  sim::CourtScenarioOptions scenario;
  double min_radius_px = 2.0;  // smaller balls are neither labelled nor wrong
  PhotoBallOptions detector = shipped_photo_ball_options();  // ballsight's detector

  static constexpr int kMaxScenes = 1000;
  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct TennisSimMethod {
  std::string method;                           // "ballsight", "report-hsv"
  std::map<std::string, BallMatch> conditions;  // by sim::light_condition_name
  BallMatch total;
};

struct TennisSimResult {
  std::vector<TennisSimMethod> methods;  // ballsight, then the report's HSV detector
};

TennisSimResult run_tennis_sim(const TennisSimOptions& options);

/// The frames of `options.scenes` scenes as a labelled source ("simulator") to fit the detector
/// on: the labels of eval tennis-sim, every other sphere ignored (LabelledPhotos::ignored).
LabelledPhotos simulated_labelled_photos(const TennisSimOptions& options);
/// The simulator's source the detector's settings are fitted on beside the real photos
/// (`detect fit --sim-scenes`, eval detect-real): `scenes` scenes of `seed` at 1920x1080, the
/// court cameras' size, with distractors (leaves, a bottle).
LabelledPhotos simulated_fitting_photos(int scenes, std::uint64_t seed = 1);

nlohmann::json tennis_sim_json(const TennisSimResult& result);
std::string tennis_sim_table(const TennisSimResult& result);

}  // namespace ballsight
