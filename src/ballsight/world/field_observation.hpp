#pragma once
// Pixel -> field: the ray through a detection's centre meets the horizontal plane at the object's
// centre height (a ball's radius, a marker's height above the floor), not the floor, and the
// detection's expected pixel error becomes an expected position error on that plane (it grows
// with the distance and stretches along the line of sight where the ray grazes the plane).

#include <Eigen/Core>
#include <optional>

#include "ballsight/camera/field_camera.hpp"
#include "ballsight/core/pixel_detection.hpp"

namespace ballsight {

/// One camera's view of one object, on the field.
struct FieldObservation {
  ObjectClass object = ObjectClass::ball;
  Vec2 position_m = Vec2::Zero();  // the object's centre, horizontal, field frame
  Eigen::Matrix2d covariance_m2 = Eigen::Matrix2d::Identity();  // its expected error
  int camera = 0;                                               // camera index in the site
  int detection = 0;                                            // index in that camera's detections
  double range_m = 0.0;                                         // distance from the camera
  double objects = 1.0;    // how many objects its share of its blob amounts to
  int split_count = 1;     // parts its blob was split into (PixelDetection::split_count)
  double radius_px = 0.0;  // the detection\'s apparent radius (a blob of several: larger)
  /// Plane position per pixel of the detection's centre (2 x 2): maps image offsets to the plane.
  Eigen::Matrix2d plane_per_pixel = Eigen::Matrix2d::Identity();
};

struct ObservationNoise {
  /// What the calibration adds to every detection's own expected error, as pixels (the
  /// reprojection error of the reference points is the natural value).
  double calibration_sigma_px = 0.15;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// The observation of `detection` by `camera`, the object's centre at `center_height_m`; nullopt
/// where the ray does not meet that plane in front of the camera.
std::optional<FieldObservation> observe_on_plane(const FieldCamera& camera,
                                                 const PixelDetection& detection,
                                                 double center_height_m,
                                                 const ObservationNoise& noise);

/// Mahalanobis distance squared between two observations' positions (their errors independent).
double mahalanobis_squared(const Vec2& a, const Eigen::Matrix2d& covariance_a, const Vec2& b,
                           const Eigen::Matrix2d& covariance_b);

}  // namespace ballsight
