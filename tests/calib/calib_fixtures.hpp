#pragma once
// Shared set-ups of the calib tests: the paper's misaligned rig and its simulated calibration.

#include <functional>
#include <string>

#include "ballsight/calib/simulated_calibration.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight::test {

/// A rig misaligned as the omnivision paper describes: tilted 1.5 deg, image centre ~5 px off.
inline OmniRigParams paper_misaligned_rig(double tilt_azimuth_deg = 30.0) {
  OmniRigParams params;
  params.tilt_deg = 1.5;
  params.tilt_azimuth_deg = tilt_azimuth_deg;
  params.center_offset_px = {4.0, -3.0};
  return params;
}

/// The paper's marker layout (60 .. 460 cm every 50 cm, every 10 deg), 1 px click noise.
inline SimulatedCalibrationOptions paper_markers(std::uint64_t seed) {
  SimulatedCalibrationOptions options;
  options.seed = seed;
  return options;
}

/// The message of the InputError `f` throws; empty when it throws none.
inline std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace ballsight::test
