#include "ballsight/calib/omni_ground_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

void OmniImage::validate() const {
  const auto size_ok = [](int n) { return n >= 16 && n <= 16384; };
  require(size_ok(width) && size_ok(height), "image size",
          "expected width and height in [16, 16384] px, got " + std::to_string(width) + "x" +
              std::to_string(height));
  require(center_px.allFinite() && center_px.x() >= 0.0 && center_px.y() >= 0.0 &&
              center_px.x() <= width - 1.0 && center_px.y() <= height - 1.0,
          "image centre",
          "expected a point inside the " + std::to_string(width) + "x" + std::to_string(height) +
              " image");
}

bool OmniImage::contains(double theta_deg, double radius_px) const {
  const Vec2 pixel = pixel_from_image_polar({theta_deg, radius_px}, center_px);
  return pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() <= width - 0.5 &&
         pixel.y() <= height - 0.5;
}

RadiusRange valid_radius_from_samples(std::span<const PolarSample> samples,
                                      double margin_fraction) {
  require(!samples.empty(), "samples", "none given");
  const auto [lo, hi] = std::minmax_element(
      samples.begin(), samples.end(),
      [](const PolarSample& a, const PolarSample& b) { return a.radius_px < b.radius_px; });
  const double margin = std::max(1.0, margin_fraction * (hi->radius_px - lo->radius_px));
  return {std::max(0.0, lo->radius_px - margin), hi->radius_px + margin};
}

OmniImage omni_image_for_samples(std::span<const PolarSample> samples,
                                 const std::optional<Vec2>& center_px,
                                 const std::optional<Eigen::Vector2i>& size) {
  require(!samples.empty(), "samples", "none given");
  double max_radius = 0.0;
  for (const PolarSample& s : samples) max_radius = std::max(max_radius, s.radius_px);
  const double covered = std::ceil(1.1 * max_radius + 8.0);  // radii plus margin
  OmniImage image;
  if (size) {
    image.width = size->x();
    image.height = size->y();
  } else if (center_px) {
    image.width = static_cast<int>(std::ceil(std::max(center_px->x(), 0.0) + covered)) + 1;
    image.height = static_cast<int>(std::ceil(std::max(center_px->y(), 0.0) + covered)) + 1;
  } else {
    image.width = image.height = 2 * static_cast<int>(covered);
  }
  image.center_px = center_px.value_or(Vec2(0.5 * (image.width - 1), 0.5 * (image.height - 1)));
  image.validate();
  const Vec2 far_corner(
      std::max(image.center_px.x() + 0.5, image.width - 0.5 - image.center_px.x()),
      std::max(image.center_px.y() + 0.5, image.height - 0.5 - image.center_px.y()));
  require(max_radius <= far_corner.norm(), "image size",
          "the samples reach " + std::to_string(max_radius) +
              " px from the centre, beyond every corner of the image");
  return image;
}

Vec2 robot_point_cm_from_prediction(const GroundPrediction& prediction, double theta_deg) {
  const double direction_deg = prediction.bearing_deg.value_or(theta_deg);
  return robot_point_from_bearing(robot_bearing_deg_from_image_theta_deg(direction_deg),
                                  prediction.distance_cm);
}

std::optional<Vec2> OmniGroundModel::robot_point_cm(const Vec2& pixel) const {
  const Polar polar = image_polar_from_pixel(pixel, domain().image.center_px);
  const GroundPrediction prediction = predict(polar.theta_deg, polar.radius);
  if (!prediction.in_range || !std::isfinite(prediction.distance_cm)) return std::nullopt;
  return robot_point_cm_from_prediction(prediction, polar.theta_deg);
}

}  // namespace ballsight
