#include "ballsight/world/ball_support.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/error.hpp"
#include "ballsight/core/raycast_box.hpp"

namespace ballsight {

void BallSupportOptions::validate() const {
  require(min_radius_px >= 0.0, "ball support min_radius_px", "must be non-negative");
  require(robot_margin_m >= 0.0, "ball support robot_margin_m", "must be non-negative");
  if (net) net->validate();
  require(same_place_radii >= 0.0 && min_same_place_px >= 0.0, "ball support",
          "same_place_radii and min_same_place_px must be non-negative");
}

namespace {

double apparent_radius(const FieldCamera& camera, double distance_m, double radius_m) {
  return camera.camera.params().fx * radius_m / distance_m;
}

}  // namespace

MissReason explain_miss(const FieldCamera& camera, const Vec3& center_in_field, double radius_m,
                        const std::vector<FusedBall>& balls, std::size_t self,
                        const std::vector<PixelDetection>& detections,
                        const std::optional<Pose2D>& robot_pose, const RobotModel& robot,
                        const BallSupportOptions& options) {
  const std::optional<Vec2> pixel = camera.pixel_from_field(center_in_field);
  if (!pixel || !camera.camera.in_image(*pixel)) return MissReason::out_of_view;
  const Vec3 eye = camera.center_in_field();
  const double distance = (center_in_field - eye).norm();
  const double r = apparent_radius(camera, distance, radius_m);
  if (r < options.min_radius_px) return MissReason::too_small;
  if (robot_pose &&
      box_hides(eye, center_in_field, robot.body(*robot_pose, options.robot_margin_m)))
    return MissReason::behind_robot;
  if (options.net && options.net->hides(eye, center_in_field)) return MissReason::behind_net;
  const double same_place = std::max(options.min_same_place_px, options.same_place_radii * r);
  // A detection right there, or a blob (of several touching balls) reaching over it.
  for (const PixelDetection& d : detections)
    if (d.object == ObjectClass::ball &&
        (d.center_px - *pixel).norm() <= std::max(same_place, d.radius_px))
      return MissReason::detected_there;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (i == self) continue;
    const Vec3 other(balls[i].position_m.x(), balls[i].position_m.y(), center_in_field.z());
    const double other_distance = (other - eye).norm();
    if (other_distance >= distance) continue;
    const std::optional<Vec2> other_pixel = camera.pixel_from_field(other);
    // Its centre behind the nearer ball's disc: at least half of it hidden.
    if (other_pixel &&
        (*other_pixel - *pixel).norm() < apparent_radius(camera, other_distance, radius_m))
      return MissReason::behind_ball;
  }
  return MissReason::unexplained;
}

std::vector<bool> supported_balls(
    const std::vector<FusedBall>& balls, const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections, double radius_m,
    const std::optional<Pose2D>& robot_pose, const RobotModel& robot,
    const BallSupportOptions& options) {
  options.validate();
  std::vector<bool> kept(balls.size(), true);
  for (std::size_t b = 0; b < balls.size(); ++b) {
    const FusedBall& ball = balls[b];
    const Vec3 center(ball.position_m.x(), ball.position_m.y(), radius_m);
    int against = 0;
    for (std::size_t c = 0; c < cameras.size(); ++c) {
      if (!detections[c]) continue;
      if (std::find(ball.cameras.begin(), ball.cameras.end(), static_cast<int>(c)) !=
          ball.cameras.end())
        continue;
      if (explain_miss(cameras[c], center, radius_m, balls, b, *detections[c], robot_pose, robot,
                       options) == MissReason::unexplained)
        ++against;
    }
    kept[b] = against < static_cast<int>(ball.cameras.size());
  }
  return kept;
}

}  // namespace ballsight
