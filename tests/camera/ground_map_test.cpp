#include "ballsight/camera/ground_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "camera/rig_tables.hpp"

namespace ballsight {
namespace {

using test::misaligned_rig_params;
using test::rig_table_info;
using test::true_ground_cm;

class GroundMapFromTrueRig : public ::testing::Test {
 protected:
  OmniRig rig{misaligned_rig_params()};
  GroundMap map = build_ground_map(true_ground_cm(rig), rig_table_info());
};

TEST_F(GroundMapFromTrueRig, SubPixelQueriesInsideTheValidRangeAreWithinHalfACentimetre) {
  const unsigned seed = 31337;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  const GroundMapInfo& info = map.info();
  std::uniform_real_distribution<double> theta(0.0, 360.0);
  std::uniform_real_distribution<double> radius(info.min_radius_px, info.max_radius_px);
  double worst_cm = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const Vec2 pixel = pixel_from_image_polar({theta(rng), radius(rng)}, info.image_center_px);
    const std::optional<Vec2> table = map.robot_point_cm(pixel);
    const std::optional<Vec2> truth = true_ground_cm(rig)(pixel);
    ASSERT_TRUE(table && truth) << pixel.transpose();
    worst_cm = std::max(worst_cm, (*table - *truth).norm());
  }
  EXPECT_LT(worst_cm, 0.5);
  EXPECT_GT(worst_cm, 1e-4);  // the interpolation is really exercised, not a copy of the truth
}

TEST_F(GroundMapFromTrueRig, DistanceIsStrictlyIncreasingAlongRaysOverTheValidRange) {
  const GroundMapInfo& info = map.info();
  for (double theta_deg = 0.0; theta_deg < 360.0; theta_deg += 2.5) {
    double previous_cm = -1.0;
    for (double r = info.min_radius_px + 1e-9; r <= info.max_radius_px; r += 0.1) {
      const std::optional<Vec2> p_cm =
          map.robot_point_cm(pixel_from_image_polar({theta_deg, r}, info.image_center_px));
      ASSERT_TRUE(p_cm) << theta_deg << " deg, " << r << " px";
      ASSERT_GT(p_cm->norm(), previous_cm) << theta_deg << " deg, " << r << " px";
      previous_cm = p_cm->norm();
    }
  }
}

TEST_F(GroundMapFromTrueRig, IntegerPixelsReadTheBakedMappingExactly) {
  for (int y = 40; y < 440; y += 7) {
    for (int x = 100; x < 540; x += 7) {
      const Vec2 pixel(x, y);
      const GroundCell cell = map.at(x, y);
      if (!map.in_valid_range(pixel)) continue;
      const std::optional<Vec2> truth = true_ground_cm(rig)(pixel);
      ASSERT_TRUE(cell.valid() && truth);
      EXPECT_EQ(cell.x_cm, static_cast<float>(truth->x()));
      EXPECT_EQ(cell.y_cm, static_cast<float>(truth->y()));
      const std::optional<Vec2> query = map.robot_point_cm(pixel);
      ASSERT_TRUE(query);
      EXPECT_NEAR((*query - *truth).norm(), 0.0, 1e-4);
    }
  }
}

TEST_F(GroundMapFromTrueRig, OutsideTheImageOrRangeIsInvalid) {
  EXPECT_FALSE(map.at(-1, 10).valid());
  EXPECT_FALSE(map.at(640, 10).valid());
  EXPECT_FALSE(map.at(10, 480).valid());
  EXPECT_FALSE(map.at(0, 0).valid());      // a corner: far outside the mirror's annulus
  EXPECT_FALSE(map.at(320, 240).valid());  // the centre: inside the robot's own shadow
  const Vec2 center = map.info().image_center_px;
  EXPECT_FALSE(map.robot_point_cm(center + Vec2(29.0, 0.0)));
  EXPECT_TRUE(map.robot_point_cm(center + Vec2(30.5, 0.0)));
  EXPECT_TRUE(map.robot_point_cm(center + Vec2(199.5, 0.0)));
  EXPECT_FALSE(map.robot_point_cm(center + Vec2(201.0, 0.0)));
  EXPECT_FALSE(map.robot_point_cm({-1e9, 5.0}));
}

TEST(GroundMap, ForwardInTheImageIsForwardOnTheRobot) {
  const OmniRig rig;  // aligned
  GroundMapInfo info = rig_table_info();
  info.image_center_px = rig.principal_point();
  const GroundMap map = build_ground_map(true_ground_cm(rig), info);
  const std::optional<Vec2> ahead = map.robot_point_cm(info.image_center_px + Vec2(0.0, -150.0));
  ASSERT_TRUE(ahead);
  EXPECT_GT(ahead->x(), 100.0);
  EXPECT_NEAR(ahead->y(), 0.0, 1e-3);
}

TEST(GroundMap, RejectsInconsistentConstruction) {
  GroundMapInfo info;
  info.width = 4;
  info.height = 3;
  EXPECT_THROW(GroundMap(info, std::vector<GroundCell>(11)), InputError);
  EXPECT_NO_THROW(GroundMap(info, std::vector<GroundCell>(12)));
  info.max_radius_px = info.min_radius_px;
  EXPECT_THROW(info.validate(), InputError);
  info = {};
  info.method = std::string(64, 'm');
  EXPECT_THROW(info.validate(), InputError);
  info = {};
  info.image_center_px.x() = std::nan("");
  EXPECT_THROW(info.validate(), InputError);
}

}  // namespace
}  // namespace ballsight
