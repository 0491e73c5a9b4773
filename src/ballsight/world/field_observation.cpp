#include "ballsight/world/field_observation.hpp"

#include <Eigen/LU>
#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void ObservationNoise::validate() const {
  require(std::isfinite(calibration_sigma_px) && calibration_sigma_px >= 0.0,
          "observation noise calibration_sigma_px", "must be non-negative");
}

std::optional<FieldObservation> observe_on_plane(const FieldCamera& camera,
                                                 const PixelDetection& detection,
                                                 double center_height_m,
                                                 const ObservationNoise& noise) {
  const Vec2& pixel = detection.center_px;
  const std::optional<Vec3> center = camera.point_at_height(pixel, center_height_m);
  if (!center) return std::nullopt;
  // Jacobian of the plane point by the pixel, by forward differences of half a pixel (two more
  // rays; the map is smooth at this scale, and each ray is a Newton solve through the lens).
  constexpr double kStep = 0.5;
  Eigen::Matrix2d jacobian;
  for (int axis = 0; axis < 2; ++axis) {
    const std::optional<Vec3> moved =
        camera.point_at_height(pixel + kStep * Vec2::Unit(axis), center_height_m);
    if (!moved) return std::nullopt;
    jacobian.col(axis) = (moved->head<2>() - center->head<2>()) / kStep;
  }
  const double sigma2 = detection.center_sigma_px * detection.center_sigma_px +
                        noise.calibration_sigma_px * noise.calibration_sigma_px;
  FieldObservation out;
  out.object = detection.object;
  out.position_m = center->head<2>();
  out.covariance_m2 = sigma2 * jacobian * jacobian.transpose();
  out.range_m = (*center - camera.center_in_field()).norm();
  out.objects = detection.blob_objects / detection.split_count;
  out.split_count = detection.split_count;
  out.plane_per_pixel = jacobian;
  out.radius_px = detection.radius_px;
  return out;
}

double mahalanobis_squared(const Vec2& a, const Eigen::Matrix2d& covariance_a, const Vec2& b,
                           const Eigen::Matrix2d& covariance_b) {
  const Vec2 d = a - b;
  return d.dot((covariance_a + covariance_b).inverse() * d);
}

}  // namespace ballsight
