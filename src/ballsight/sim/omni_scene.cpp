#include "ballsight/sim/omni_scene.hpp"

#include <cmath>
#include <set>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {

void OmniScene::validate() const {
  rig.validate();
  field.validate();
  effects.validate();
  require(robot_pose.position.allFinite() && std::isfinite(robot_pose.heading_rad),
          "scene.robot_pose", "position and heading must be finite");
  require(std::isfinite(robot_body_radius_m) && robot_body_radius_m >= 0.0 &&
              robot_body_radius_m <= 1.0,
          "scene.robot_body_radius_m", "must be in [0, 1] m");

  // Objects stand outside the robot's footprint and within 100 m (beyond, the mirror image is
  // a single pixel anyway).
  const auto require_placed = [&](const Vec2& p, double radius, const std::string& where) {
    require(p.allFinite(), where + ".position_in_field", "must be finite");
    const double distance = (p - robot_pose.position).norm();
    require(distance >= robot_body_radius_m + radius, where + ".position_in_field",
            "lies under the robot's body (" + std::to_string(distance) +
                " m from the robot, needs at least robot_body_radius_m + radius_m)");
    require(distance <= 100.0, where + ".position_in_field", "is more than 100 m from the robot");
  };
  if (ball) {
    require(std::isfinite(ball->radius_m) && ball->radius_m >= 0.02 && ball->radius_m <= 0.5,
            "scene.ball.radius_m", "must be in [0.02, 0.5] m");
    require_placed(ball->position_in_field, ball->radius_m, "scene.ball");
  }
  std::set<int> ids;
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const FloorMarker& m = markers[i];
    const std::string where = "scene.markers[" + std::to_string(i) + "]";
    require(ids.insert(m.id).second, where + ".id", "duplicate id " + std::to_string(m.id));
    require(std::isfinite(m.radius_m) && m.radius_m >= 0.005 && m.radius_m <= 1.0,
            where + ".radius_m", "must be in [0.005, 1] m");
    require_placed(m.position_in_field, m.radius_m, where);
  }
}

}  // namespace ballsight::sim
