#pragma once
// A camera's calibration file: OpenCV FileStorage YAML with OpenCV's key names (`image_width`,
// `image_height`, `camera_matrix`, `distortion_coefficients`, `avg_reprojection_error`), plus the
// camera's pose on its site once `court calibrate` has found it (`rvec`, `tvec` of
// camera_from_field, `extrinsics_reprojection_error`, `extrinsics_reference_count`). Reading also
// accepts a ROS camera_info YAML (camera_calibration_parsers' format). Layout: docs/site-file.md.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// A fixed camera's pose on its site, from reference points.
struct CameraExtrinsics {
  Rigid3 camera_from_field;            // p_in_camera = camera_from_field * p_in_field
  double reprojection_error_px = 0.0;  // rms over the reference points used
  int reference_count = 0;             // reference points used
};

/// What a calibration file holds: the intrinsics and, once known, the pose.
struct CameraCalibration {
  PinholeParams intrinsics;
  std::optional<double> avg_reprojection_error_px;  // of the intrinsic calibration
  std::optional<CameraExtrinsics> extrinsics;
};

enum class CameraFileFormat { opencv, ros_camera_info };

/// A parsed file and the format it was in.
struct CameraFile {
  CameraCalibration calibration;
  CameraFileFormat format = CameraFileFormat::opencv;
};

/// Parses the text of a calibration file; `name` (the file) prefixes every error. A ROS
/// camera_info is recognised by its `distortion_model` key (plumb_bob or rational_polynomial).
/// Throws InputError "<name>:<line>: key '<key>' ..." for a missing or malformed key, or
/// "<name>:<line>:<column>: not valid YAML: ...". Keys it does not know are allowed.
CameraFile parse_camera_file(std::string_view text, const std::string& name);

/// Reads and parses a calibration file; throws InputError naming the file (and the key).
CameraCalibration read_camera_file(const std::filesystem::path& path);

/// The calibration as OpenCV FileStorage YAML (5 distortion coefficients unless k4-k6 are used).
std::string camera_file_text(const CameraCalibration& calibration);

/// Writes camera_file_text atomically: an existing file is replaced whole or left untouched.
void write_camera_file(const std::filesystem::path& path, const CameraCalibration& calibration);

}  // namespace ballsight
