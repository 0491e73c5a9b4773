#include "ballsight/world/court_world.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/world/cluster_refinement.hpp"

namespace ballsight {

void CourtWorldOptions::validate() const {
  require(std::isfinite(ball_radius_m) && ball_radius_m > 0.0, "world ball_radius_m",
          "must be positive");
  robot.validate();
  noise.validate();
  fusion.validate();
  clusters.validate();
  pixel_fit.validate();
  support.validate();
  obstacles.validate();
  require(std::isfinite(collector_width_m) && collector_width_m > 0.0, "world collector_width_m",
          "must be positive");
  require(area.valid(), "world area", "must have a positive size");
}

std::vector<cv::Point2f> robot_outline_px(const FieldCamera& camera, const Pose2D& robot_pose,
                                          const RobotModel& robot) {
  const Rigid2 field_from_robot = robot_pose.field_from_robot();
  std::vector<cv::Point2f> corners;
  for (double x : {-0.5 * robot.length_m, 0.5 * robot.length_m}) {
    for (double y : {-0.5 * robot.width_m, 0.5 * robot.width_m}) {
      const Vec2 p = field_from_robot * Vec2(x, y);
      for (double z : {0.0, robot.height_m}) {
        const std::optional<Vec2> pixel = camera.pixel_from_field(Vec3(p.x(), p.y(), z));
        if (!pixel) return {};
        corners.emplace_back(static_cast<float>(pixel->x()), static_cast<float>(pixel->y()));
      }
    }
  }
  std::vector<cv::Point2f> hull;
  cv::convexHull(corners, hull);
  return hull;
}

namespace {

// A ball whose image touches the robot's may be partly hidden by it: its centre can be off by up
// to about its radius, so its expected error grows by that much.
void account_for_robot(const std::vector<cv::Point2f>& outline, PixelDetection& detection) {
  if (outline.size() < 3) return;
  const cv::Point2f center(static_cast<float>(detection.center_px.x()),
                           static_cast<float>(detection.center_px.y()));
  const double signed_distance = cv::pointPolygonTest(outline, center, true);
  if (signed_distance < -(detection.radius_px + 1.5)) return;
  detection.center_sigma_px = std::hypot(detection.center_sigma_px, detection.radius_px);
}

}  // namespace

double object_center_height_m(ObjectClass object, const CourtWorldOptions& options) {
  if (object == ObjectClass::obstacle) return 0.0;  // where it stands
  return object == ObjectClass::ball ? options.ball_radius_m : options.robot.marker_height_m;
}

WorldModel build_world_model(
    const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections,
    const CourtWorldOptions& options) {
  options.validate();
  require_list_per_camera(cameras.size(), detections.size(), "world model");
  WorldModel model;
  std::vector<FieldObservation> fronts, backs, balls;
  const auto place = [&](size_t camera, int index, const PixelDetection& detection,
                         std::vector<FieldObservation>& into) {
    std::optional<FieldObservation> o =
        observe_on_plane(cameras[camera], detection,
                         object_center_height_m(detection.object, options), options.noise);
    if (!o || !options.area.contains(o->position_m)) return;
    o->camera = static_cast<int>(camera);
    o->detection = index;
    into.push_back(*o);
  };
  for (size_t c = 0; c < cameras.size(); ++c) {
    if (!detections[c]) continue;
    model.cameras.push_back(static_cast<int>(c));
    const std::vector<PixelDetection>& list = *detections[c];
    for (size_t i = 0; i < list.size(); ++i) {
      if (list[i].object == ObjectClass::robot_front_marker)
        place(c, static_cast<int>(i), list[i], fronts);
      if (list[i].object == ObjectClass::robot_back_marker)
        place(c, static_cast<int>(i), list[i], backs);
    }
  }
  model.robot = estimate_robot_pose(fronts, backs, options.robot, options.fusion);

  for (size_t c = 0; c < cameras.size(); ++c) {
    if (!detections[c]) continue;
    const std::vector<cv::Point2f> outline =
        model.robot ? robot_outline_px(cameras[c], model.robot->pose, options.robot)
                    : std::vector<cv::Point2f>{};
    const std::vector<PixelDetection>& list = *detections[c];
    for (size_t i = 0; i < list.size(); ++i) {
      if (list[i].object != ObjectClass::ball) continue;
      PixelDetection detection = list[i];
      account_for_robot(outline, detection);
      place(c, static_cast<int>(i), detection, balls);
    }
  }
  std::vector<FusedBall> fused;
  const std::vector<FusedObject> refined = refine_clusters(
      balls, fuse_observations(balls, options.fusion), options.ball_radius_m, options.clusters);
  // Pixels where the robot's body stands in front of the balls' plane: no evidence either way.
  HiddenPixel hidden;
  if (model.robot) {
    const FloorBox body = options.robot.body(model.robot->pose, options.support.robot_margin_m);
    hidden = [&cameras, body, &options](int camera, const Vec2& pixel) {
      const FieldCamera& c = cameras[static_cast<size_t>(camera)];
      const std::optional<Vec3> on_plane = c.point_at_height(pixel, options.ball_radius_m);
      return on_plane && box_hides(c.center_in_field(), *on_plane, body);
    };
  }
  for (const FusedObject& object : fit_clusters_to_pixels(
           balls, refined, detections, options.ball_radius_m, options.pixel_fit, hidden))
    fused.push_back({object.position_m, object.covariance_m2, object.cameras});
  const std::vector<bool> kept =
      supported_balls(fused, cameras, detections, options.ball_radius_m,
                      model.robot ? std::optional<Pose2D>(model.robot->pose) : std::nullopt,
                      options.robot, options.support);
  for (size_t i = 0; i < fused.size(); ++i)
    if (kept[i]) model.balls.push_back(fused[i]);
  std::sort(model.balls.begin(), model.balls.end(), [](const FusedBall& a, const FusedBall& b) {
    return a.position_m.x() < b.position_m.x() ||
           (a.position_m.x() == b.position_m.x() && a.position_m.y() < b.position_m.y());
  });
  std::vector<Vec2> positions;
  for (const FusedBall& ball : model.balls) positions.push_back(ball.position_m);
  model.sites = collection_sites(positions, options.collector_width_m);
  model.obstacles = locate_floor_obstacles(
      cameras, detections, model.robot ? std::optional<Pose2D>(model.robot->pose) : std::nullopt,
      options.robot, model.balls, options.area, options.obstacles);
  return model;
}

}  // namespace ballsight
