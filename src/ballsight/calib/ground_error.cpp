#include "ballsight/calib/ground_error.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "ballsight/core/conventions.hpp"

namespace ballsight {

namespace {

class ErrorCollector {
 public:
  // Adds a query's prediction; returns false when it has no finite distance.
  bool add(const GroundPrediction& prediction, double true_distance_cm) {
    if (!std::isfinite(prediction.distance_cm)) {
      ++errors_.unmapped;
      return false;
    }
    if (!prediction.in_range) ++errors_.out_of_range;
    distance_.push_back(std::abs(prediction.distance_cm - true_distance_cm));
    return true;
  }
  void add_position(double error_cm) { position_.push_back(error_cm); }

  GroundErrors finish() {
    errors_.position_cm = summarize_errors(std::move(position_));
    errors_.distance_cm = summarize_errors(std::move(distance_));
    return errors_;
  }

 private:
  GroundErrors errors_;
  std::vector<double> position_;
  std::vector<double> distance_;
};

}  // namespace

ErrorSummary summarize_errors(std::vector<double> errors) {
  ErrorSummary summary;
  summary.count = errors.size();
  if (errors.empty()) return summary;
  std::sort(errors.begin(), errors.end());
  const auto rank = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(errors.size())));
    return errors[std::clamp<std::size_t>(k, 1, errors.size()) - 1];
  };
  summary.median = rank(0.5);
  summary.p95 = rank(0.95);
  summary.max = errors.back();
  summary.mean =
      std::accumulate(errors.begin(), errors.end(), 0.0) / static_cast<double>(errors.size());
  return summary;
}

GroundErrors ground_errors(const OmniGroundModel& model, std::span<const FloorTruth> truth) {
  ErrorCollector collector;
  for (const FloorTruth& t : truth) {
    const Polar polar = image_polar_from_pixel(t.pixel, model.domain().image.center_px);
    const GroundPrediction prediction = model.predict(polar.theta_deg, polar.radius);
    if (!collector.add(prediction, t.p_in_robot_cm.norm())) continue;
    collector.add_position(
        (robot_point_cm_from_prediction(prediction, polar.theta_deg) - t.p_in_robot_cm).norm());
  }
  return collector.finish();
}

GroundErrors sample_errors(const OmniGroundModel& model, std::span<const PolarSample> samples) {
  ErrorCollector collector;
  for (const PolarSample& s : samples) {
    const GroundPrediction prediction = model.predict(s.theta_deg, s.radius_px);
    if (!collector.add(prediction, s.distance_cm) || !s.bearing_deg) continue;
    const Vec2 truth = robot_point_from_bearing(
        robot_bearing_deg_from_image_theta_deg(*s.bearing_deg), s.distance_cm);
    collector.add_position(
        (robot_point_cm_from_prediction(prediction, s.theta_deg) - truth).norm());
  }
  return collector.finish();
}

}  // namespace ballsight
