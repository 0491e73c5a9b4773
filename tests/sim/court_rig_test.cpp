#include "ballsight/sim/court_rig.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_scenario.hpp"

namespace ballsight::sim {
namespace {

constexpr std::uint64_t kSeeds[] = {1, 2, 3, 17, 20240611};

TEST(CourtRig, FourPolesAtTheCornersLookingIn) {
  const TennisCourtSpec court;
  for (const std::uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const CourtRig rig = make_court_rig(court, {}, seed);
    ASSERT_EQ(rig.cameras.size(), 4u);
    int quadrants = 0;
    for (const CourtCamera& c : rig.cameras) {
      const Vec3 eye = c.center_in_field();
      EXPECT_NEAR(std::abs(eye.x()), court.surround_length_m / 2 + 0.25, 0.25);
      EXPECT_NEAR(std::abs(eye.y()), court.surround_width_m / 2 + 0.25, 0.25);
      EXPECT_GE(eye.z(), 4.0);
      EXPECT_LE(eye.z(), 6.0);
      quadrants |= 1 << ((eye.x() > 0 ? 1 : 0) + (eye.y() > 0 ? 2 : 0));
      // The court centre is in front of the camera and the field's up is up in the image.
      const auto centre = c.camera.project(c.camera_from_field * Vec3::Zero());
      const auto above = c.camera.project(c.camera_from_field * Vec3(0, 0, 1));
      ASSERT_TRUE(centre && above);
      EXPECT_LT(above->y(), centre->y());
    }
    EXPECT_EQ(quadrants, 0b1111) << "one camera per corner";
  }
}

TEST(CourtRig, EveryCameraSeesTheWholeCourtAndEveryReferenceBall) {
  const TennisCourtSpec court;
  for (const std::uint64_t seed : kSeeds) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    for (const CourtCamera& c : make_court_rig(court, {}, seed).cameras) {
      for (double x = -court.length_m / 2; x <= court.length_m / 2 + 1e-9;
           x += court.length_m / 8) {
        for (double y = -court.doubles_width_m / 2; y <= court.doubles_width_m / 2 + 1e-9;
             y += court.doubles_width_m / 4) {
          const auto pixel = c.camera.project(c.camera_from_field * Vec3(x, y, 0));
          ASSERT_TRUE(pixel);
          EXPECT_TRUE(c.camera.in_image(*pixel)) << x << ", " << y << " -> " << pixel->transpose();
        }
      }
      for (const Vec3& p : reference_ball_positions(court)) {
        const auto pixel = c.camera.project(c.camera_from_field * p);
        ASSERT_TRUE(pixel);
        EXPECT_TRUE(c.camera.in_image(*pixel));
      }
    }
  }
}

TEST(CourtRig, WideLensWithRealisticDistortion) {
  for (const CourtCamera& c : make_court_rig({}, {}, 5).cameras) {
    const PinholeParams& p = c.camera.params();
    EXPECT_EQ(p.width, 1280);
    EXPECT_EQ(p.height, 720);
    EXPECT_GE(p.distortion[0], -0.35);
    EXPECT_LE(p.distortion[0], -0.25);
    EXPECT_GE(p.distortion[1], 0.08);
    EXPECT_LE(p.distortion[1], 0.12);
    EXPECT_LT(std::abs(p.distortion[2]) + std::abs(p.distortion[3]), 2e-3);
    // Horizontal field of view through the distortion, edge to edge: 90 deg +- the fx jitter.
    const auto left = c.camera.unproject({-0.5, p.cy});
    const auto right = c.camera.unproject({p.width - 0.5, p.cy});
    ASSERT_TRUE(left && right);
    EXPECT_NEAR(deg_from_rad(std::acos(left->dot(*right))), 90.0, 2.5);
    // The whole image is inside the lens model's invertible region.
    for (const Vec2& corner : {Vec2(0.0, 0.0), Vec2(p.width - 1.0, p.height - 1.0)}) {
      EXPECT_TRUE(c.camera.unproject(corner)) << corner.transpose();
    }
  }
}

TEST(CourtRig, SameSeedSameRigDifferentSeedDifferentRig) {
  const CourtRig a = make_court_rig({}, {}, 42), b = make_court_rig({}, {}, 42);
  const CourtRig c = make_court_rig({}, {}, 43);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(a.cameras[i].camera.params().fx, b.cameras[i].camera.params().fx);
    EXPECT_EQ(a.cameras[i].camera_from_field.translation,
              b.cameras[i].camera_from_field.translation);
    EXPECT_NE(a.cameras[i].camera.params().fx, c.cameras[i].camera.params().fx);
  }
}

TEST(CourtRig, LookAtPutsTheTargetOnTheOpticalAxis) {
  const Vec3 eye(18, 9, 5), target(2, -1, 0);
  const Rigid3 camera_from_field = camera_from_field_looking_at(eye, target, 0.3);
  const Vec3 t = camera_from_field * target;
  EXPECT_NEAR(t.x(), 0.0, 1e-12);
  EXPECT_NEAR(t.y(), 0.0, 1e-12);
  EXPECT_NEAR(t.z(), (target - eye).norm(), 1e-12);
  EXPECT_NEAR((camera_from_field * eye).norm(), 0.0, 1e-12);
  EXPECT_NEAR(camera_from_field.rotation.determinant(), 1.0, 1e-12);
}

TEST(CourtRig, ResolutionIsConfigurableAndValidated) {
  CourtRigOptions options;
  options.width = 1920;
  options.height = 1080;
  EXPECT_EQ(make_court_rig({}, options, 1).cameras[0].camera.width(), 1920);
  options.width = 0;
  EXPECT_THROW(make_court_rig({}, options, 1), InputError);
  options = {};
  options.pole_height_max_m = 3.0;
  EXPECT_THROW(make_court_rig({}, options, 1), InputError);
  options = {};
  options.hfov_deg = std::nan("");
  EXPECT_THROW(make_court_rig({}, options, 1), InputError);
}

}  // namespace
}  // namespace ballsight::sim
