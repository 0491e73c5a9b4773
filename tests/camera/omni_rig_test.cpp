#include "ballsight/camera/omni_rig.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

double radius_px_at(const OmniRig& rig, double distance_m, double bearing_deg) {
  const Vec2 p = robot_point_from_bearing(bearing_deg, distance_m);
  const auto pixel = rig.pixel_from_point({p.x(), p.y(), 0.0});
  EXPECT_TRUE(pixel) << distance_m << " m";
  return pixel ? (*pixel - rig.principal_point()).norm() : 0.0;
}

TEST(OmniRig, DefaultProfileResemblesTableI) {
  const OmniRig rig;
  // Table I of the omnivision paper (around 0 deg); the real rows scatter by ~10 px.
  const std::pair<double, double> table[] = {
      {0.6, 81.0}, {1.1, 105.0}, {1.6, 145.0}, {2.1, 160.0}, {2.6, 172.0}};
  for (const auto& [distance_m, radius_px] : table) {
    EXPECT_NEAR(radius_px_at(rig, distance_m, 0.0), radius_px, 10.0) << distance_m << " m";
  }
  // Usable to 6 m: still inside the mirror and still resolving 10 cm steps.
  EXPECT_GT(radius_px_at(rig, 6.1, 0.0) - radius_px_at(rig, 6.0, 0.0), 0.05);
}

TEST(OmniRig, ImageUpIsRobotForward) {
  const OmniRig rig;
  const auto ahead = rig.pixel_from_point({2.0, 0.0, 0.0});
  ASSERT_TRUE(ahead);
  const Polar polar = image_polar_from_pixel(*ahead, rig.principal_point());
  EXPECT_NEAR(polar.theta_deg, 90.0, 1e-9);
  const auto left = rig.pixel_from_point({0.0, 2.0, 0.0});
  ASSERT_TRUE(left);
  EXPECT_NEAR(image_polar_from_pixel(*left, rig.principal_point()).theta_deg, 180.0, 1e-9);
}

TEST(OmniRig, GroundRoundTripOverDenseGridWithMisalignment) {
  OmniRigParams params;
  params.tilt_deg = 2.0;
  params.tilt_azimuth_deg = 35.0;
  params.center_offset_px = {4.0, -3.0};
  const OmniRig rig(params);
  int checked = 0;
  for (double y = 0.0; y < 480.0; y += 2.1) {
    for (double x = 0.0; x < 640.0; x += 2.1) {
      const auto ground = rig.ground_from_pixel({x, y});
      if (!ground) continue;
      const auto back = rig.pixel_from_point({ground->x(), ground->y(), 0.0});
      ASSERT_TRUE(back);
      ASSERT_NEAR((*back - Vec2(x, y)).norm(), 0.0, 1e-6) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30000);
}

TEST(OmniRig, TiltBendsTheProfileByDirection) {
  OmniRigParams params;
  params.tilt_deg = 2.0;
  const OmniRig tilted(params);
  const double towards = radius_px_at(tilted, 2.0, 0.0);
  const double away = radius_px_at(tilted, 2.0, 180.0);
  EXPECT_GT(std::abs(towards - away), 2.0);  // the paper's point: one polynomial cannot fit all
}

TEST(OmniRig, RejectsInvalidParameters) {
  OmniRigParams params;
  params.tilt_deg = 45.0;
  EXPECT_THROW(OmniRig{params}, InputError);
  params = {};
  params.height_m = -1.0;
  EXPECT_THROW(OmniRig{params}, InputError);
}

}  // namespace
}  // namespace ballsight
