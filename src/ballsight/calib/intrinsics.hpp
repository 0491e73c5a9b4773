#pragma once
// Intrinsic calibration from chessboard views (Zhang's method through cv::calibrateCamera), made
// robust: k3 stays fixed at 0 unless freeing it lowers the error on held-out views (with k3 free
// from the start, OpenCV's optimiser can stall in a wrong minimum under strong barrel distortion,
// docs/sim-court.md), and views whose error stands out are dropped one by one and the rest
// recalibrated.

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/calib/chessboard_corners.hpp"
#include "ballsight/camera/pinhole.hpp"

namespace ballsight {

/// The corners found in one image, named after it.
struct ChessboardView {
  std::string name;
  std::vector<cv::Point2f> corners;  // ChessboardPattern::object_points() order
};

struct IntrinsicsOptions {
  int min_views = 4;            // views needed after dropping outliers
  double outlier_factor = 3.0;  // a view is an outlier when its rms error exceeds this many
  double outlier_min_px = 0.5;  // times the median view's, and this many pixels
  int folds = 4;                // cross-validation folds for the k3 decision (5 views or more)
  double k3_min_gain = 0.03;    // free k3 only if it lowers the held-out rms error by 3%

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// A view's rms reprojection error under the final calibration.
struct ViewError {
  std::string name;
  double rms_px = 0.0;
  bool outlier = false;  // dropped from the calibration
};

struct IntrinsicsResult {
  PinholeParams camera;
  double rms_px = 0.0;           // over every corner of the views used (avg_reprojection_error)
  std::vector<ViewError> views;  // every view given, in order
  bool k3_free = false;
  std::optional<double> heldout_rms_fixed_k3_px;  // cross-validation, when it was run
  std::optional<double> heldout_rms_free_k3_px;
};

/// Calibrates a pinhole camera with OpenCV's 5-coefficient distortion from the views. Throws
/// InputError when fewer than options.min_views views remain or OpenCV fails.
IntrinsicsResult calibrate_intrinsics(const std::vector<ChessboardView>& views,
                                      const ChessboardPattern& pattern, cv::Size image_size,
                                      const IntrinsicsOptions& options = {});

/// A view's rms reprojection error under a given calibration, the board posed by PnP (IPPE, then
/// Levenberg-Marquardt): checks a calibration on views it was not fitted to.
double view_rms_px(const ChessboardView& view, const ChessboardPattern& pattern,
                   const PinholeCamera& camera);

}  // namespace ballsight
