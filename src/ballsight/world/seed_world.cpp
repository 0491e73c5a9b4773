#include "ballsight/world/seed_world.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

void SeedWorldOptions::validate() const {
  require(std::isfinite(z_const_m), "seed world z_const_m", "must be finite");
  require(std::isfinite(merge_distance_m) && merge_distance_m >= 0.0, "seed world merge_distance_m",
          "must be non-negative");
  robot.validate();
}

namespace {

struct Merged {
  Vec2 sum = Vec2::Zero();
  int count = 0;
  std::vector<int> cameras;

  Vec2 mean() const { return sum / count; }
};

// Section 7.8: a point within the fixed distance of an aggregated one joins it (running mean).
void aggregate(std::vector<Merged>& merged, const Vec2& p, int camera, double distance_m) {
  for (Merged& m : merged) {
    if ((m.mean() - p).norm() < distance_m) {
      m.sum += p;
      ++m.count;
      if (std::find(m.cameras.begin(), m.cameras.end(), camera) == m.cameras.end())
        m.cameras.push_back(camera);
      return;
    }
  }
  merged.push_back({p, 1, {camera}});
}

}  // namespace

WorldModel build_seed_world_model(
    const std::vector<FieldCamera>& cameras,
    const std::vector<std::optional<std::vector<PixelDetection>>>& detections,
    const SeedWorldOptions& options) {
  options.validate();
  require_list_per_camera(cameras.size(), detections.size(), "seed world model");
  WorldModel model;
  std::vector<Merged> balls;
  Merged front, back;
  for (size_t c = 0; c < cameras.size(); ++c) {
    if (!detections[c]) continue;
    const int camera = static_cast<int>(c);
    model.cameras.push_back(camera);
    const PixelDetection* largest_front = nullptr;
    const PixelDetection* largest_back = nullptr;
    for (const PixelDetection& d : *detections[c]) {
      if (d.object == ObjectClass::ball) {
        const std::optional<Vec3> p = cameras[c].point_at_height(d.center_px, options.z_const_m);
        if (p) aggregate(balls, p->head<2>(), camera, options.merge_distance_m);
      } else if (d.object != ObjectClass::obstacle) {  // the report looks for no obstacles
        const PixelDetection*& largest =
            d.object == ObjectClass::robot_front_marker ? largest_front : largest_back;
        if (!largest || d.area_px > largest->area_px) largest = &d;
      }
    }
    for (auto [marker, into] : {std::pair{largest_front, &front}, std::pair{largest_back, &back}}) {
      if (!marker) continue;
      const std::optional<Vec3> p =
          cameras[c].point_at_height(marker->center_px, options.z_const_m);
      if (!p) continue;
      into->sum += p->head<2>();
      ++into->count;
      into->cameras.push_back(camera);
    }
  }
  for (const Merged& m : balls) {
    FusedBall ball;
    ball.position_m = m.mean();
    ball.covariance_m2.setZero();  // the report has no error model
    ball.cameras = m.cameras;
    std::sort(ball.cameras.begin(), ball.cameras.end());
    model.sites.push_back({ball.position_m, {static_cast<int>(model.balls.size())}, 0.0});
    model.balls.push_back(std::move(ball));
  }
  if (front.count > 0 && back.count > 0) {
    RobotPoseEstimate robot;
    robot.front_marker_m = front.mean();
    robot.back_marker_m = back.mean();
    robot.pose = pose_from_markers(robot.front_marker_m, robot.back_marker_m, options.robot);
    robot.front_cameras = front.cameras;
    robot.back_cameras = back.cameras;
    model.robot = robot;
  }
  return model;
}

}  // namespace ballsight
