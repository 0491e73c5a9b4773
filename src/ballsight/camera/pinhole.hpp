#pragma once
// Pinhole camera with OpenCV's distortion model; compatible with cv::calibrateCamera output.
// Camera frame: x right, y down, z forward (OpenCV).

#include <opencv2/core.hpp>
#include <optional>

#include "ballsight/camera/distortion.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct PinholeParams {
  int width = 0;
  int height = 0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  Distortion::Coefficients distortion{};  // k1 k2 p1 p2 k3 k4 k5 k6

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class PinholeCamera {
 public:
  explicit PinholeCamera(const PinholeParams& params);

  const PinholeParams& params() const { return params_; }
  int width() const { return params_.width; }
  int height() const { return params_.height; }

  /// Point in the camera frame -> pixel; nullopt behind the camera or outside the region where
  /// the distortion model is invertible. The pixel may lie outside the image.
  std::optional<Vec2> project(const Vec3& p_in_camera) const;
  /// Pixel -> unit ray in the camera frame; nullopt where the model is not invertible.
  std::optional<Vec3> unproject(const Vec2& pixel) const;

  bool in_image(const Vec2& pixel) const;

  cv::Matx33d camera_matrix() const;
  /// The 8 coefficients as a 1x8 CV_64F row, OpenCV's order.
  cv::Mat distortion_coefficients() const;
  /// From OpenCV's camera matrix and 4, 5 or 8 distortion coefficients.
  static PinholeCamera from_opencv(const cv::Matx33d& camera_matrix, const cv::Mat& distortion,
                                   cv::Size image_size);

 private:
  PinholeParams params_;
  Distortion distortion_;
};

}  // namespace ballsight
