#include "ballsight/calib/marker_samples.hpp"

#include <string>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

PolarSample sample_from_marker(const MarkerObservation& marker, const Vec2& image_center,
                               const std::string& where) {
  require(marker.pixel.allFinite(), where, "pixel must be finite");
  require(marker.p_in_robot.allFinite(), where, "position must be finite");
  const Polar image = image_polar_from_pixel(marker.pixel, image_center);  // Algorithm 2
  require(image.radius > 0.0, where, "pixel lies on the image centre");
  const Polar ground = polar_from_cartesian(marker.p_in_robot);
  require(ground.radius > 0.0, where, "marker lies under the robot centre");
  PolarSample sample;
  sample.theta_deg = image.theta_deg;
  sample.radius_px = image.radius;
  sample.distance_cm = 100.0 * ground.radius;
  sample.bearing_deg = wrap_deg_360(image_theta_deg_from_robot_bearing_deg(ground.theta_deg));
  return sample;
}

std::vector<PolarSample> samples_from_markers(std::span<const MarkerObservation> markers,
                                              const Vec2& image_center) {
  std::vector<PolarSample> samples;
  samples.reserve(markers.size());
  for (std::size_t i = 0; i < markers.size(); ++i) {
    samples.push_back(sample_from_marker(markers[i], image_center, "marker " + std::to_string(i)));
  }
  return samples;
}

std::vector<PolarSample> samples_from_field_markers(std::span<const FieldMarkerObservation> markers,
                                                    const Pose2D& robot_pose,
                                                    const Vec2& image_center) {
  require(robot_pose.position.allFinite() && std::isfinite(robot_pose.heading_rad), "robot pose",
          "must be finite");
  std::vector<MarkerObservation> in_robot;
  in_robot.reserve(markers.size());
  for (const FieldMarkerObservation& m : markers) {
    in_robot.push_back({m.pixel, robot_from_field_point(robot_pose, m.p_in_field)});
  }
  return samples_from_markers(in_robot, image_center);
}

}  // namespace ballsight
