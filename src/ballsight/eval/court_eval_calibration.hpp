#pragma once
// How each method of the court evaluation gets its cameras: from rendered chessboard views
// (intrinsics) and a rendered view of the empty court with its reference balls (pose), never from
// the simulator's truth.
//
// - ballsight: calib's robust intrinsics (k3 only when held-out views ask for it, outlier views
//   dropped) and the court calibration of `court calibrate` (colour-weighted reference blobs, P3P
//   over unlabelled triples, refinement).
// - seed: the report's way (sections 7.2-7.3): a plain cv::calibrateCamera with the Matlab
//   toolbox's default model (two radial coefficients, no tangential ones), the reference balls
//   found by its own HSV threshold and contour moments, and cv::solvePnP on them. The report's
//   user types in which ball is which; here the matching step of the court calibration does that.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/detect/seed_detector.hpp"
#include "ballsight/service/simulated_court.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct CalibrationImages {
  std::vector<std::vector<cv::Mat>> chessboards;  // per camera, its chessboard views
  std::vector<cv::Mat> reference_views;           // per camera, the court with reference balls
};

/// `views` chessboard views per camera and one reference view per camera of an empty court (the
/// robot parked on it), rendered with sensor noise `noise_sigma`; deterministic for a seed.
CalibrationImages render_calibration_images(const sim::CourtRig& rig, int views, double noise_sigma,
                                            std::uint64_t seed);

/// The report's HSV box for reference balls of the site's colour: its OpenCV hue (0-179) +-12,
/// saturation and value from 70 and 40 (0-22 for the orange table-tennis balls).
HsvRange report_reference_box(const Rgb& colour);

/// One method's calibrated cameras and how well each fit (rms reprojection errors, px).
struct EvalCalibration {
  std::vector<FieldCamera> cameras;
  std::vector<double> intrinsics_rms_px;
  std::vector<double> pose_rms_px;
};

EvalCalibration calibrate_ballsight_cameras(const CalibrationImages& images, const Site& site);
EvalCalibration calibrate_seed_cameras(const CalibrationImages& images, const Site& site);

}  // namespace ballsight
