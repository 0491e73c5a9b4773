#pragma once
// Scoring a court world model against the simulator's truth (definitions in docs/court-eval.md):
//
// - A true ball counts for recall when the simulator says at least one camera sees it (centre in
//   the image, at least half of it unoccluded); the others are counted as unseen, apart.
// - Estimates and true balls (seen or not) are matched one to one, nearest pairs first, within
//   the match radius. An estimate matched to a counted ball is a true positive; one matched to an
//   unseen ball is a correct extra (a real ball), neither a hit nor a false positive.
// - An unmatched estimate within the match radius of a matched true ball is a duplicate (two
//   estimates of one ball); any other unmatched estimate is a false positive.
// - recall = true positives / counted balls; precision = (true positives + correct extras) /
//   estimates. Ball error: distance of each true positive to its ball.

#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct TruthBall {
  Vec2 position_m = Vec2::Zero();
  bool seen = true;  // visible in at least one camera
};

/// One ball a method got wrong: a counted ball it missed (the true position), or an estimate that
/// is a duplicate or a false positive (the estimated position).
struct BallMistake {
  enum class Kind { missed, duplicate, false_positive };
  Kind kind = Kind::missed;
  Vec2 position_m = Vec2::Zero();
  int scene = 0;  // set by CourtScores::add
};

/// "missed", "duplicate", "false_positive".
std::string mistake_kind_name(BallMistake::Kind kind);

struct SceneScore {
  int counted = 0;  // true balls that count for recall
  int unseen = 0;   // true balls no camera sees
  int estimates = 0;
  int true_positives = 0;
  int correct_extras = 0;  // estimates of unseen balls
  int duplicates = 0;
  int false_positives = 0;
  std::vector<double> errors_m;  // one per true positive
  std::vector<BallMistake> mistakes;
  bool robot_found = false;
  double robot_position_error_m = 0.0;  // when found
  double robot_heading_error_rad = 0.0;
};

/// Scores one frame set's balls and robot.
SceneScore score_scene(const std::vector<TruthBall>& truth, const std::vector<Vec2>& estimates,
                       const Pose2D& robot_truth, const std::optional<Pose2D>& robot_estimate,
                       double match_radius_m);

/// Sums over scenes and the figures docs/court-eval.md reports.
struct CourtScores {
  int scenes = 0;
  int counted = 0, unseen = 0, estimates = 0;
  int true_positives = 0, correct_extras = 0, duplicates = 0, false_positives = 0;
  std::vector<double> errors_m;
  std::vector<BallMistake> mistakes;  // scene: index of the scene in the order added
  int robot_found = 0;
  std::vector<double> robot_position_errors_m, robot_heading_errors_rad;

  void add(const SceneScore& scene);
  double recall() const;
  double precision() const;
  double ball_error_mean_m() const;
  double ball_error_p95_m() const;
  double robot_position_error_mean_m() const;
  double robot_position_error_max_m() const;
  double robot_heading_error_mean_rad() const;
  double robot_heading_error_max_rad() const;
};

/// The q-quantile (0-1) of `values` (nearest rank); NaN when empty.
double quantile(std::vector<double> values, double q);

}  // namespace ballsight
