#include "ballsight/world/ball_on_floor.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void BallOnFloor::validate() const {
  require(std::isfinite(radius_cm) && radius_cm > 0.0, "ball", "radius_cm must be positive");
  require(std::isfinite(viewpoint_height_cm) && viewpoint_height_cm > radius_cm, "ball",
          "viewpoint_height_cm must exceed the ball radius (is the table's height known?)");
}

Vec2 ball_center_from_floor_hit_cm(const Vec2& floor_hit_cm, const BallOnFloor& ball) {
  return floor_hit_cm * ((ball.viewpoint_height_cm - ball.radius_cm) / ball.viewpoint_height_cm);
}

std::optional<Vec2> ball_center_in_robot_cm(const GroundMap& map, const Vec2& ball_center_px,
                                            const BallOnFloor& ball) {
  const std::optional<Vec2> floor_hit = map.robot_point_cm(ball_center_px);
  if (!floor_hit) return std::nullopt;
  return ball_center_from_floor_hit_cm(*floor_hit, ball);
}

}  // namespace ballsight
