#pragma once
// A simulated marker calibration session (Section III-A of the omnivision paper) on an OmniRig
// with known truth: floor markers on rings and rays, clicked with pixel noise, some mislabelled;
// and held-out floor pixels with their true ground points, to measure a fitted model.

#include <cstdint>
#include <vector>

#include "ballsight/calib/marker_samples.hpp"
#include "ballsight/camera/omni_rig.hpp"

namespace ballsight {

struct SimulatedCalibrationOptions {
  double min_distance_cm = 60.0;  // the paper's markers: 60 to 460 cm
  double max_distance_cm = 460.0;
  int rings = 9;                         // distances, evenly spaced (9: every 50 cm)
  int rays = 36;                         // bearings, evenly spaced (36: every 10 deg)
  double click_noise_px = 1.0;           // Gaussian, per pixel axis
  int mislabelled = 0;                   // samples labelled with a neighbouring ring's distance
  bool with_bearing = true;              // whether samples carry the true bearing
  Vec2 assumed_center_px{319.5, 239.5};  // the centre the samples are taken around
  std::uint64_t seed = 1;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct SimulatedCalibration {
  std::vector<MarkerObservation> markers;  // clicked pixels, true positions
  std::vector<PolarSample> samples;        // one per marker, some mislabelled
  std::vector<std::size_t> mislabelled;    // indices of the mislabelled samples
};

/// Markers the rig images (inside its mirror) become samples around the assumed centre.
SimulatedCalibration simulate_calibration(const OmniRig& rig,
                                          const SimulatedCalibrationOptions& options);

/// A pixel with the true floor point it sees.
struct FloorTruth {
  Vec2 pixel = Vec2::Zero();
  Vec2 p_in_robot_cm = Vec2::Zero();
};

/// `count` floor points uniform over the ring min..max cm, at their exact pixels.
std::vector<FloorTruth> random_floor_truth(const OmniRig& rig, double min_distance_cm,
                                           double max_distance_cm, int count, std::uint64_t seed);

}  // namespace ballsight
