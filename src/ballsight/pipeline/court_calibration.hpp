#pragma once
// `court calibrate` (and the court calibration page, one camera at a time): every camera of a
// site takes a still frame from its source (pipeline: still_frame, any source kind), finds the
// reference balls in it (detect: colour blobs), fits its pose to them (calib: reference_pose) and
// the pose goes into the camera's calibration file (camera: camera_file). Every camera is tried;
// the files are written only when all succeeded, so one failing camera leaves every file as it
// was.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/calib/reference_pose.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/detect/color_blobs.hpp"
#include "ballsight/pipeline/still_frame.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct CourtCalibrationOptions {
  ColorBlobOptions blobs;  // target_bgr is taken from the site's reference-ball colour
  ReferencePoseOptions pose;
  StillFrameOptions frame;  // how each camera's still is taken from its source
};

/// One camera's extrinsic calibration and what it was made from.
struct CameraPoseReport {
  std::string camera;  // the site's name for it
  std::string source;  // where the still came from ("file court_0000_cam0.png", a URL)
  std::filesystem::path calibration_file;
  int blob_count = 0;               // blobs of the reference-ball colour
  std::vector<Vec2> candidates_px;  // their centroids, most reliable first
  std::vector<ReferencePoint> references;
  ReferencePose pose;
  CameraCalibration calibration;  // the file's content with the new pose
};

/// A camera that could not be calibrated, and why (the message names the camera).
struct CameraCalibrationFailure {
  std::string camera;
  std::string error;
};

struct SiteCalibration {
  std::vector<CameraPoseReport> calibrated;  // in site order
  std::vector<CameraCalibrationFailure> failed;
  bool written = false;  // the poses went into the calibration files (only when none failed)
};

/// The site's reference balls as points (centres at z = radius), in file order.
std::vector<ReferencePoint> site_references(const Site& site);

/// Extrinsics of one camera from `image` (taken from `source`) under `calibration`'s intrinsics,
/// with what a user said of single reference balls (indices into site_references()). Throws
/// InputError naming the camera and source when the image size differs from the calibration's or
/// too few reference balls are found.
CameraPoseReport calibrate_site_camera(const Site& site, const SiteCamera& camera,
                                       const cv::Mat& image, const std::string& source,
                                       const CameraCalibration& calibration,
                                       const CourtCalibrationOptions& options = {},
                                       const ReferenceCorrections& corrections = {});

/// Calibrates every camera of the site (reading its calibration file and a still from its
/// source), then, when none failed, writes each pose into its calibration file (atomically).
SiteCalibration calibrate_site(const Site& site, const CourtCalibrationOptions& options = {});

}  // namespace ballsight
