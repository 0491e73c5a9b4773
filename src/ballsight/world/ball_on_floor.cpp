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

namespace {

// Unit ray from the viewpoint through the floor point of a map cell.
std::optional<Vec3> cell_ray(const GroundMap& map, int x, int y, double height_cm) {
  const GroundCell cell = map.at(x, y);
  if (!cell.valid()) return std::nullopt;
  return Vec3(cell.x_cm, cell.y_cm, -height_cm).normalized();
}

}  // namespace

std::optional<Vec2> ball_center_from_silhouette_cm(const GroundMap& map,
                                                   std::span<const cv::Point> silhouette,
                                                   const BallOnFloor& ball) {
  ball.validate();
  const double h = ball.viewpoint_height_cm;
  Vec3 sum = Vec3::Zero();
  for (const cv::Point& p : silhouette) {
    const auto ray = cell_ray(map, p.x, p.y, h);
    const auto right = cell_ray(map, p.x + 1, p.y, h);
    const auto down = cell_ray(map, p.x, p.y + 1, h);
    if (!ray || !right || !down) continue;
    // The pixel's solid angle, from the rays of its neighbours.
    const double solid_angle = (*right - *ray).cross(*down - *ray).norm();
    sum += solid_angle * *ray;
  }
  if (!(sum.z() < 0.0)) return std::nullopt;
  const Vec3 axis = sum.normalized();
  // From the viewpoint (0, 0, h) down the axis to the height of the ball's centre.
  return axis.head<2>() * ((ball.radius_cm - h) / axis.z());
}

}  // namespace ballsight
