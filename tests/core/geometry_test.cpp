#include "ballsight/core/geometry.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/angle.hpp"

namespace ballsight {
namespace {

constexpr unsigned kSeed = 20261122;

TEST(Angle, WrapsIntoRange) {
  EXPECT_DOUBLE_EQ(wrap_deg_360(-90.0), 270.0);
  EXPECT_DOUBLE_EQ(wrap_deg_360(720.0), 0.0);
  EXPECT_DOUBLE_EQ(wrap_deg_360(359.5), 359.5);
  EXPECT_GE(wrap_deg_360(-1e-17), 0.0);
  EXPECT_LT(wrap_deg_360(-1e-17), 360.0);
  EXPECT_DOUBLE_EQ(wrap_deg_180(190.0), -170.0);
  EXPECT_DOUBLE_EQ(wrap_deg_180(-180.0), -180.0);
  EXPECT_NEAR(wrap_rad_pi(3.0 * kPi / 2.0), -kPi / 2.0, 1e-12);
  EXPECT_NEAR(deg_from_rad(rad_from_deg(123.4)), 123.4, 1e-12);
}

TEST(Polar, RoundTripsThroughCartesian) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> coord(-500.0, 500.0);
  for (int i = 0; i < 1000; ++i) {
    const Vec2 v(coord(rng), coord(rng));
    const Polar p = polar_from_cartesian(v);
    EXPECT_GE(p.theta_deg, 0.0);
    EXPECT_LT(p.theta_deg, 360.0);
    EXPECT_NEAR((cartesian_from_polar(p) - v).norm(), 0.0, 1e-9);
  }
  EXPECT_NEAR(polar_from_cartesian({0.0, 2.0}).theta_deg, 90.0, 1e-12);
  EXPECT_NEAR(polar_from_cartesian({-1.0, -1e-12}).theta_deg, 180.0, 1e-6);
}

TEST(Pose2D, MovesAlongAnArc) {
  const Pose2D straight = along_arc({Vec2(1, 2), 0.5}, 2.0, 0.0, 0.5);
  EXPECT_NEAR((straight.position - Vec2(1, 2) - Vec2(std::cos(0.5), std::sin(0.5))).norm(), 0.0,
              1e-12);
  EXPECT_DOUBLE_EQ(straight.heading_rad, 0.5);
  // A quarter circle of radius 1 m, counter-clockwise from heading 0.
  const Pose2D quarter = along_arc({Vec2(0, 0), 0.0}, 1.0, 1.0, kPi / 2.0);
  EXPECT_NEAR((quarter.position - Vec2(1, 1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(quarter.heading_rad, kPi / 2.0, 1e-12);
  const Pose2D spin = along_arc({Vec2(3, 3), 3.0}, 0.0, 1.0, 0.5);  // on the spot, wrapped
  EXPECT_EQ(spin.position, Vec2(3, 3));
  EXPECT_NEAR(spin.heading_rad, 3.5 - 2.0 * kPi, 1e-12);
}

TEST(Pose2D, APointAheadAlongTheHeading) {
  const Pose2D pose{Vec2(1, 2), kPi / 2.0};
  EXPECT_NEAR((pose.ahead(0.3) - Vec2(1, 2.3)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((pose.ahead(-0.5) - Vec2(1, 1.5)).norm(), 0.0, 1e-12);
  EXPECT_EQ(pose.ahead(0.0), Vec2(1, 2));
}

TEST(Rigid2, ComposesAndInverts) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int i = 0; i < 200; ++i) {
    const Rigid2 a_from_b{{u(rng), u(rng)}, u(rng)};
    const Rigid2 b_from_c{{u(rng), u(rng)}, u(rng)};
    const Vec2 p_in_c(u(rng), u(rng));
    EXPECT_NEAR(((a_from_b * b_from_c) * p_in_c - a_from_b * (b_from_c * p_in_c)).norm(), 0.0,
                1e-9);
    EXPECT_NEAR((a_from_b.inverse() * (a_from_b * p_in_c) - p_in_c).norm(), 0.0, 1e-9);
    const Rigid2 identity = a_from_b * a_from_b.inverse();
    EXPECT_NEAR(identity.translation.norm(), 0.0, 1e-9);
    EXPECT_NEAR(identity.theta_rad, 0.0, 1e-9);
  }
  // A quarter turn takes +x to +y.
  EXPECT_NEAR(((Rigid2{{1.0, 2.0}, kPi / 2}) * Vec2(1.0, 0.0) - Vec2(1.0, 3.0)).norm(), 0.0, 1e-12);
}

TEST(Rigid3, ComposesInvertsAndRoundTripsRvec) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Rigid3 a_from_b =
        Rigid3::from_rvec_tvec({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
    const Rigid3 b_from_c =
        Rigid3::from_rvec_tvec({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(((a_from_b * b_from_c) * p - a_from_b * (b_from_c * p)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((a_from_b.inverse() * (a_from_b * p) - p).norm(), 0.0, 1e-12);
    const Rigid3 again = Rigid3::from_rvec_tvec(a_from_b.rvec(), a_from_b.translation);
    EXPECT_NEAR((again.rotation - a_from_b.rotation).norm(), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace ballsight
