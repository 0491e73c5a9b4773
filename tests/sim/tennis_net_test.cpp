#include "ballsight/sim/tennis_net.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {
namespace {

TennisNet default_net() {
  return TennisNet::of(TennisCourtSpec{}).value();
}

TEST(TennisNet, PostsAndCordFollowTheItfRules) {
  const TennisNet net = default_net();
  // Post centres 0.914 m outside the doubles sidelines (10.97 m apart).
  const auto posts = net.post_positions();
  EXPECT_NEAR(posts[0].x(), 0.0, 1e-12);
  EXPECT_NEAR(posts[0].y(), -6.399, 1e-12);
  EXPECT_NEAR(posts[1].y(), 6.399, 1e-12);
  EXPECT_NEAR(net.top_height_m(0.0), 0.914, 1e-12);
  EXPECT_NEAR(net.top_height_m(-6.399), 1.07, 1e-12);
  EXPECT_NEAR(net.top_height_m(6.399 / 2), (0.914 + 1.07) / 2, 1e-12) << "straight to the strap";
  TennisCourtSpec no_net;
  no_net.net.enabled = false;
  EXPECT_FALSE(TennisNet::of(no_net));
}

TEST(TennisNet, RaysAcrossTheNetLineHitMeshBandOrNothing) {
  const TennisNet net = default_net();
  const Vec3 along(-1.0, 0.0, 0.0);
  const auto hit_at = [&](double y, double z) { return net.intersect(Vec3(5.0, y, z), along); };
  const auto mesh = hit_at(2.0, 0.5);
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->part, NetPart::mesh);
  EXPECT_NEAR(mesh->t, 5.0, 1e-12);
  EXPECT_EQ(mesh->normal_in_field, Vec3::UnitX()) << "facing the ray's origin";
  const double top = net.top_height_m(2.0);
  EXPECT_EQ(hit_at(2.0, top - 0.07)->part, NetPart::mesh);
  EXPECT_EQ(hit_at(2.0, top - 0.05)->part, NetPart::band) << "6 cm band";
  EXPECT_EQ(hit_at(2.0, top - 0.001)->part, NetPart::band);
  EXPECT_FALSE(hit_at(2.0, top + 0.001)) << "over the cord";
  EXPECT_FALSE(hit_at(7.0, 0.5)) << "beyond the post";
  EXPECT_FALSE(net.intersect(Vec3(-5.0, 2.0, 0.5), along)) << "the net is behind the ray";
  const auto from_behind = net.intersect(Vec3(-5.0, 2.0, 0.5), -along);
  ASSERT_TRUE(from_behind);
  EXPECT_EQ(from_behind->normal_in_field, -Vec3::UnitX());
  EXPECT_FALSE(net.intersect(Vec3(5.0, 2.0, 0.5), Vec3::UnitY())) << "parallel to the net";
}

TEST(TennisNet, PostsAreRoundWithAFlatTop) {
  const TennisNet net = default_net();
  const Vec2 post = net.post_positions()[1];
  // Head on from +x at 0.5 m: the post's face is r in front of its axis.
  const auto side = net.intersect(Vec3(5.0, post.y(), 0.5), Vec3(-1.0, 0.0, 0.0));
  ASSERT_TRUE(side);
  EXPECT_EQ(side->part, NetPart::post);
  EXPECT_NEAR(side->t, 5.0 - 0.04, 1e-12);
  EXPECT_NEAR((side->normal_in_field - Vec3::UnitX()).norm(), 0.0, 1e-12);
  // Grazing the post 3 cm off its axis: the side's normal tilts by asin(0.03 / 0.04).
  const auto off = net.intersect(Vec3(5.0, post.y() + 0.03, 0.5), Vec3(-1.0, 0.0, 0.0));
  ASSERT_TRUE(off);
  EXPECT_EQ(off->part, NetPart::post);
  EXPECT_NEAR(off->normal_in_field.y(), 0.75, 1e-12);
  EXPECT_NEAR(off->t, 5.0 - std::sqrt(0.04 * 0.04 - 0.03 * 0.03), 1e-12);
  // Straight down onto the top: 1.07 m high.
  const auto cap = net.intersect(Vec3(0.01, post.y(), 3.0), -Vec3::UnitZ());
  ASSERT_TRUE(cap);
  EXPECT_EQ(cap->part, NetPart::post);
  EXPECT_NEAR(cap->t, 3.0 - 1.07, 1e-12);
  EXPECT_EQ(cap->normal_in_field, Vec3::UnitZ());
  EXPECT_FALSE(net.intersect(Vec3(5.0, post.y(), 1.08), Vec3(-1.0, 0.0, 0.0))) << "over the post";
  EXPECT_FALSE(net.intersect(Vec3(5.0, post.y() + 0.041, 0.5), Vec3(-1.0, 0.0, 0.0)));
}

TEST(TennisNet, EveryHitLiesOnTheNetAndFacesTheRay) {
  const TennisNet net = default_net();
  const std::uint64_t seed = 4242;
  std::mt19937_64 rng(seed);
  int hits[3] = {0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    // From the corners' camera poles towards a point in the net's box, or near it.
    const Vec3 origin(uniform(rng, -20.0, 20.0), uniform(rng, -10.0, 10.0), uniform(rng, 0.1, 6.0));
    const Vec3 target(uniform(rng, -0.1, 0.1), uniform(rng, -6.6, 6.6), uniform(rng, 0.0, 1.2));
    const Vec3 d = (target - origin).normalized();
    const auto hit = net.intersect(origin, d);
    if (!hit) continue;
    SCOPED_TRACE("seed " + std::to_string(seed) + ", ray " + std::to_string(i));
    ++hits[static_cast<int>(hit->part)];
    const Vec3 p = origin + hit->t * d;
    EXPECT_LT(hit->normal_in_field.dot(d), 0.0);
    EXPECT_NEAR(hit->normal_in_field.norm(), 1.0, 1e-9);
    if (hit->part == NetPart::post) {
      const Vec2 post = net.post_positions()[p.y() > 0.0 ? 1 : 0];
      const double from_axis = (p.head<2>() - post).norm();
      const bool on_side = std::abs(from_axis - 0.04) < 1e-9 && p.z() >= 0.0 && p.z() <= 1.07;
      const bool on_top = std::abs(p.z() - 1.07) < 1e-9 && from_axis <= 0.04 + 1e-9;
      EXPECT_TRUE(on_side || on_top) << p.transpose();
    } else {
      EXPECT_NEAR(p.x(), 0.0, 1e-9);
      EXPECT_LE(p.z(), net.top_height_m(p.y()) + 1e-9);
      EXPECT_GE(p.z(), -1e-9);
      EXPECT_EQ(hit->part == NetPart::band, p.z() >= net.top_height_m(p.y()) - 0.06);
    }
  }
  EXPECT_GT(hits[0], 1000) << "mesh";
  EXPECT_GT(hits[1], 50) << "band";
  EXPECT_GT(hits[2], 5) << "posts";
}

TEST(TennisNet, InvalidNetSpecsAreNamed) {
  const auto expect_named = [](const TennisCourtSpec& court, const std::string& field) {
    try {
      court.validate();
      ADD_FAILURE() << "expected InputError naming " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  TennisCourtSpec court;
  court.net.centre_height_m = 1.2;
  expect_named(court, "court.net.centre_height_m");
  court = {};
  court.net.post_radius_m = 0.1;
  expect_named(court, "court.net.post_radius_m");
  court = {};
  court.net.band_depth_m = 0.0;
  expect_named(court, "court.net.band_depth_m");
  court = {};
  court.net.post_outside_doubles_m = 4.0;
  expect_named(court, "court.net.post_outside_doubles_m");
  court = {};
  court.net.post_height_m = -1.0;
  expect_named(court, "court.net.post_height_m");
  court = {};
  court.net.enabled = false;
  EXPECT_NO_THROW(court.validate());
}

}  // namespace
}  // namespace ballsight::sim
