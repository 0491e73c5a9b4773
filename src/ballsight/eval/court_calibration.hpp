#pragma once
// `court calibrate`: every camera of a site finds the reference balls in its first source image
// (detect: colour blobs), fits its pose to them (calib: reference_pose) and the pose goes into the
// camera's calibration file (camera: camera_file). All cameras are calibrated before any file is
// written, so one failing camera leaves every file as it was.

#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ballsight/calib/reference_pose.hpp"
#include "ballsight/camera/camera_file.hpp"
#include "ballsight/detect/color_blobs.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct CourtCalibrationOptions {
  ColorBlobOptions blobs;  // target_bgr is taken from the site's reference-ball colour
  ReferencePoseOptions pose;
};

/// One camera's extrinsic calibration and what it was made from.
struct CameraPoseReport {
  std::string camera;  // the site's name for it
  std::filesystem::path image;
  std::filesystem::path calibration_file;
  int blob_count = 0;  // blobs of the reference-ball colour
  std::vector<ReferencePoint> references;
  ReferencePose pose;
  CameraCalibration calibration;  // the file's content with the new pose
};

/// The image a camera is calibrated from: the file of a `file` source, the first image (by
/// name) of a `folder` source. Throws InputError for other sources or an empty folder.
std::filesystem::path first_source_image(const SiteCamera& camera);

/// The site's reference balls as points (centres at z = radius), in file order.
std::vector<ReferencePoint> site_references(const Site& site);

/// Extrinsics of one camera from `image` under `calibration`'s intrinsics. Throws InputError
/// naming the camera and image when the image size differs from the calibration's or too few
/// reference balls are found.
CameraPoseReport calibrate_site_camera(const Site& site, const SiteCamera& camera,
                                       const cv::Mat& image,
                                       const std::filesystem::path& image_file,
                                       const CameraCalibration& calibration,
                                       const CourtCalibrationOptions& options = {});

/// Calibrates every camera of the site, then writes each pose into its calibration file
/// (atomically; nothing is written when any camera fails).
std::vector<CameraPoseReport> calibrate_site(const Site& site,
                                             const CourtCalibrationOptions& options = {});

}  // namespace ballsight
