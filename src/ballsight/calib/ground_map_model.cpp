#include "ballsight/calib/ground_map_model.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"

namespace ballsight {

GroundMapModel::GroundMapModel(GroundMap map) : map_(std::move(map)) {
  const GroundMapInfo& info = map_.info();
  domain_.image = {info.width, info.height, info.image_center_px};
  domain_.valid_radius = {info.min_radius_px, info.max_radius_px};
}

GroundPrediction GroundMapModel::predict(double theta_deg, double radius_px) const {
  GroundPrediction prediction;
  prediction.distance_cm = std::numeric_limits<double>::quiet_NaN();
  const Vec2 pixel = pixel_from_image_polar({theta_deg, radius_px}, domain_.image.center_px);
  const std::optional<Vec2> p_in_robot_cm = map_.robot_point_cm(pixel);
  if (!p_in_robot_cm) return prediction;  // outside the valid range: flagged, no value
  const Polar ground = polar_from_cartesian(*p_in_robot_cm);
  prediction.distance_cm = ground.radius;
  prediction.bearing_deg = wrap_deg_360(image_theta_deg_from_robot_bearing_deg(ground.theta_deg));
  prediction.in_range = true;
  return prediction;
}

nlohmann::json GroundMapModel::parameters_json() const {
  return {{"lookup_table_method", map_.info().method}};
}

std::optional<double> GroundMapModel::viewpoint_height_cm() const {
  const double height = map_.info().viewpoint_height_cm;
  return height > 0.0 ? std::optional<double>(height) : std::nullopt;
}

}  // namespace ballsight
