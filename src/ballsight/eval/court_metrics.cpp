#include "ballsight/eval/court_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

#include "ballsight/core/angle.hpp"

namespace ballsight {

std::string mistake_kind_name(BallMistake::Kind kind) {
  switch (kind) {
    case BallMistake::Kind::missed:
      return "missed";
    case BallMistake::Kind::duplicate:
      return "duplicate";
    case BallMistake::Kind::false_positive:
      return "false_positive";
  }
  return "unknown";
}

SceneScore score_scene(const std::vector<TruthBall>& truth, const std::vector<Vec2>& estimates,
                       const Pose2D& robot_truth, const std::optional<Pose2D>& robot_estimate,
                       double match_radius_m) {
  SceneScore score;
  for (const TruthBall& t : truth) ++(t.seen ? score.counted : score.unseen);
  score.estimates = static_cast<int>(estimates.size());

  // One-to-one matching, nearest pairs first, within the radius.
  std::vector<std::tuple<double, size_t, size_t>> pairs;
  for (size_t t = 0; t < truth.size(); ++t)
    for (size_t e = 0; e < estimates.size(); ++e) {
      const double d = (truth[t].position_m - estimates[e]).norm();
      if (d <= match_radius_m) pairs.emplace_back(d, t, e);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> truth_used(truth.size(), false), estimate_used(estimates.size(), false);
  for (const auto& [d, t, e] : pairs) {
    if (truth_used[t] || estimate_used[e]) continue;
    truth_used[t] = estimate_used[e] = true;
    if (truth[t].seen) {
      ++score.true_positives;
      score.errors_m.push_back(d);
    } else {
      ++score.correct_extras;
    }
  }
  for (size_t e = 0; e < estimates.size(); ++e) {
    if (estimate_used[e]) continue;
    const bool near_matched = std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) {
      return std::get<2>(p) == e && truth_used[std::get<1>(p)];
    });
    ++(near_matched ? score.duplicates : score.false_positives);
    score.mistakes.push_back(
        {near_matched ? BallMistake::Kind::duplicate : BallMistake::Kind::false_positive,
         estimates[e]});
  }
  for (size_t t = 0; t < truth.size(); ++t)
    if (truth[t].seen && !truth_used[t])
      score.mistakes.push_back({BallMistake::Kind::missed, truth[t].position_m});
  if (robot_estimate) {
    score.robot_found = true;
    score.robot_position_error_m = (robot_estimate->position - robot_truth.position).norm();
    score.robot_heading_error_rad =
        std::abs(wrap_rad_pi(robot_estimate->heading_rad - robot_truth.heading_rad));
  }
  return score;
}

void CourtScores::add(const SceneScore& s) {
  ++scenes;
  counted += s.counted;
  unseen += s.unseen;
  estimates += s.estimates;
  true_positives += s.true_positives;
  correct_extras += s.correct_extras;
  duplicates += s.duplicates;
  false_positives += s.false_positives;
  errors_m.insert(errors_m.end(), s.errors_m.begin(), s.errors_m.end());
  for (BallMistake mistake : s.mistakes) {
    mistake.scene = scenes - 1;
    mistakes.push_back(mistake);
  }
  if (s.robot_found) {
    ++robot_found;
    robot_position_errors_m.push_back(s.robot_position_error_m);
    robot_heading_errors_rad.push_back(s.robot_heading_error_rad);
  }
}

namespace {

double mean(const std::vector<double>& v) {
  return v.empty() ? std::numeric_limits<double>::quiet_NaN()
                   : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double max_of(const std::vector<double>& v) {
  return v.empty() ? std::numeric_limits<double>::quiet_NaN()
                   : *std::max_element(v.begin(), v.end());
}

}  // namespace

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

double CourtScores::recall() const {
  return counted == 0 ? std::numeric_limits<double>::quiet_NaN()
                      : static_cast<double>(true_positives) / counted;
}
double CourtScores::precision() const {
  return estimates == 0 ? std::numeric_limits<double>::quiet_NaN()
                        : static_cast<double>(true_positives + correct_extras) / estimates;
}
double CourtScores::ball_error_mean_m() const {
  return mean(errors_m);
}
double CourtScores::ball_error_p95_m() const {
  return quantile(errors_m, 0.95);
}
double CourtScores::robot_position_error_mean_m() const {
  return mean(robot_position_errors_m);
}
double CourtScores::robot_position_error_max_m() const {
  return max_of(robot_position_errors_m);
}
double CourtScores::robot_heading_error_mean_rad() const {
  return mean(robot_heading_errors_rad);
}
double CourtScores::robot_heading_error_max_rad() const {
  return max_of(robot_heading_errors_rad);
}

}  // namespace ballsight
