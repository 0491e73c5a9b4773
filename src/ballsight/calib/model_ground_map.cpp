#include "ballsight/calib/model_ground_map.hpp"

#include <cmath>
#include <string>

#include "ballsight/core/conventions.hpp"

namespace ballsight {

GroundMapInfo ground_map_info(const OmniGroundModel& model) {
  const OmniModelDomain& domain = model.domain();
  GroundMapInfo info;
  info.width = domain.image.width;
  info.height = domain.image.height;
  info.image_center_px = domain.image.center_px;
  info.min_radius_px = domain.valid_radius.min_px;
  info.max_radius_px = domain.valid_radius.max_px;
  info.method = std::string(model.name());
  info.viewpoint_height_cm = model.viewpoint_height_cm().value_or(0.0);
  return info;
}

GroundMap ground_map_from_model(const OmniGroundModel& model) {
  const Vec2 center = model.domain().image.center_px;
  // Not robot_point_cm: the table also stores the apron just outside the valid range that
  // sub-pixel queries at its edge interpolate from; the table's header carries the range.
  const auto mapping = [&](const Vec2& pixel) -> std::optional<Vec2> {
    const Polar polar = image_polar_from_pixel(pixel, center);
    const GroundPrediction prediction = model.predict(polar.theta_deg, polar.radius);
    if (!std::isfinite(prediction.distance_cm)) return std::nullopt;
    return robot_point_cm_from_prediction(prediction, polar.theta_deg);
  };
  return build_ground_map(mapping, ground_map_info(model));
}

}  // namespace ballsight
