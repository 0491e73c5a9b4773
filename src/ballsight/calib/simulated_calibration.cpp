#include "ballsight/calib/simulated_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

void SimulatedCalibrationOptions::validate() const {
  const std::string where = "simulated calibration";
  require(
      std::isfinite(min_distance_cm) && min_distance_cm > 0.0 && max_distance_cm > min_distance_cm,
      where, "expected 0 < min_distance_cm < max_distance_cm");
  require(rings >= 2 && rays >= 1, where, "expected at least 2 rings and 1 ray");
  require(std::isfinite(click_noise_px) && click_noise_px >= 0.0, where,
          "click_noise_px must be >= 0");
  require(mislabelled >= 0, where, "mislabelled must be >= 0");
  require(assumed_center_px.allFinite(), where, "assumed_center_px must be finite");
}

SimulatedCalibration simulate_calibration(const OmniRig& rig,
                                          const SimulatedCalibrationOptions& options) {
  options.validate();
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> click(0.0, 1.0);
  const double ring_step_cm =
      (options.max_distance_cm - options.min_distance_cm) / (options.rings - 1);
  SimulatedCalibration result;
  std::vector<int> ring_of_sample;
  for (int ray = 0; ray < options.rays; ++ray) {
    const double bearing_deg = 360.0 * ray / options.rays;
    for (int ring = 0; ring < options.rings; ++ring) {
      const double distance_m = 0.01 * (options.min_distance_cm + ring * ring_step_cm);
      const Vec2 p_in_robot = robot_point_from_bearing(bearing_deg, distance_m);
      const std::optional<Vec2> pixel = rig.pixel_from_point({p_in_robot.x(), p_in_robot.y(), 0});
      if (!pixel) continue;
      const Vec2 noise(click(rng), click(rng));
      result.markers.push_back({*pixel + options.click_noise_px * noise, p_in_robot});
      ring_of_sample.push_back(ring);
    }
  }
  result.samples = samples_from_markers(result.markers, options.assumed_center_px);
  if (!options.with_bearing) {
    for (PolarSample& s : result.samples) s.bearing_deg.reset();
  }
  std::vector<std::size_t> order(result.samples.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), rng);
  const auto count = std::min(order.size(), static_cast<std::size_t>(options.mislabelled));
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = order[k];
    const int ring = ring_of_sample[i];
    const int wrong = ring + 1 < options.rings ? ring + 1 : ring - 1;  // the next marker's label
    result.samples[i].distance_cm = options.min_distance_cm + wrong * ring_step_cm;
    result.mislabelled.push_back(i);
  }
  std::sort(result.mislabelled.begin(), result.mislabelled.end());
  return result;
}

std::vector<FloorTruth> random_floor_truth(const OmniRig& rig, double min_distance_cm,
                                           double max_distance_cm, int count, std::uint64_t seed) {
  require(min_distance_cm > 0.0 && max_distance_cm > min_distance_cm && count >= 0, "floor truth",
          "expected 0 < min < max distance and count >= 0");
  std::mt19937_64 rng(seed);
  // Uniform over the ring's area: the squared distance is uniform.
  std::uniform_real_distribution<double> area(min_distance_cm * min_distance_cm,
                                              max_distance_cm * max_distance_cm);
  std::uniform_real_distribution<double> bearing(0.0, 360.0);
  std::vector<FloorTruth> truth;
  truth.reserve(static_cast<std::size_t>(count));
  int attempts = 0;
  while (static_cast<int>(truth.size()) < count && attempts++ < 100 * count) {
    const Vec2 p_cm = robot_point_from_bearing(bearing(rng), std::sqrt(area(rng)));
    const std::optional<Vec2> pixel = rig.pixel_from_point({0.01 * p_cm.x(), 0.01 * p_cm.y(), 0});
    if (pixel) truth.push_back({*pixel, p_cm});
  }
  return truth;
}

}  // namespace ballsight
