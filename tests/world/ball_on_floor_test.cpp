#include "ballsight/world/ball_on_floor.hpp"

#include <gtest/gtest.h>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/camera/rig_ground_map.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TEST(BallOnFloor, RecoversTheCentreFromTheFloorHitBehindIt) {
  OmniRigParams params;
  params.tilt_deg = 1.5;
  params.tilt_azimuth_deg = 40.0;
  const OmniRig rig(params);
  const BallOnFloor ball{11.0, rig.robot_from_camera().translation.z() * 100.0};
  for (double bearing = 0.0; bearing < 360.0; bearing += 30.0) {
    for (double distance_m : {0.8, 1.2, 2.85, 5.0}) {
      const Vec2 c = robot_point_from_bearing(bearing, distance_m);
      const auto pixel = rig.pixel_from_point({c.x(), c.y(), 0.11});
      ASSERT_TRUE(pixel);
      const auto floor_hit_m = rig.ground_from_pixel(*pixel);
      ASSERT_TRUE(floor_hit_m);
      EXPECT_GT(floor_hit_m->norm(), distance_m + 0.02);  // the naive read overshoots
      // The viewpoint sits above the robot origin, so the correction is exact up to rounding.
      EXPECT_NEAR((ball_center_from_floor_hit_cm(*floor_hit_m * 100.0, ball) - c * 100.0).norm(),
                  0.0, 1e-6);
    }
  }
}

// The silhouette of a sphere as the rig sees it: every pixel whose ray passes within the radius.
std::vector<cv::Point> silhouette(const OmniRig& rig, const Vec3& center_m, double radius_m) {
  std::vector<cv::Point> pixels;
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; ++x) {
      const auto ray = rig.viewing_ray({x, y});
      if (!ray) continue;
      const Vec3 to_center = center_m - ray->origin;
      if (to_center.cross(ray->direction).norm() < radius_m && to_center.dot(ray->direction) > 0)
        pixels.emplace_back(x, y);
    }
  }
  return pixels;
}

TEST(BallOnFloor, SilhouetteRaysPlaceTheCentreWhereThePixelCentroidDoesNot) {
  OmniRigParams params;
  params.tilt_deg = 1.5;
  const OmniRig rig(params);
  GroundMapInfo info;
  info.min_radius_px = 30.0;
  info.max_radius_px = 235.0;
  const GroundMap map = ground_map_from_rig(rig, info);
  const BallOnFloor ball{11.0, 60.0};
  for (double distance_m : {0.8, 1.2, 2.0, 2.85}) {
    const Vec2 c = robot_point_from_bearing(35.0, distance_m);
    const std::vector<cv::Point> pixels = silhouette(rig, {c.x(), c.y(), 0.11}, 0.11);
    ASSERT_GT(pixels.size(), 20u);
    const auto by_rays = ball_center_from_silhouette_cm(map, pixels, ball);
    ASSERT_TRUE(by_rays);
    EXPECT_NEAR((*by_rays - c * 100.0).norm(), 0.0, 0.25 + 0.1 * distance_m) << distance_m << " m";
    Vec2 centroid = Vec2::Zero();
    for (const cv::Point& p : pixels) centroid += Vec2(p.x, p.y);
    centroid /= static_cast<double>(pixels.size());
    const auto by_centroid = ball_center_in_robot_cm(map, centroid, ball);
    ASSERT_TRUE(by_centroid);
    if (distance_m < 1.0) {
      EXPECT_GT((*by_centroid - c * 100.0).norm(), 1.0);  // the bias the rays remove
    }
  }
}

TEST(BallOnFloor, NeedsAKnownViewpointHeight) {
  EXPECT_THROW((BallOnFloor{11.0, 0.0}).validate(), InputError);
  EXPECT_THROW((BallOnFloor{-1.0, 60.0}).validate(), InputError);
}

}  // namespace
}  // namespace ballsight
