#include "ballsight/sim/court_scenario.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/tennis_net.hpp"
#include "sim/court_test_support.hpp"

namespace ballsight::sim {
namespace {

using test_support::render_in_all_cameras;

std::vector<const SceneSphere*> of_kind(const CourtScene& scene, ObjectKind kind) {
  std::vector<const SceneSphere*> out;
  for (const SceneSphere& s : scene.balls) {
    if (s.kind == kind) out.push_back(&s);
  }
  return out;
}

TEST(CourtScenario, SameSeedSameSceneDifferentSeedDifferentScene) {
  const TennisCourtSpec court;
  const CourtScene a = make_court_scene(court, {}, 7), b = make_court_scene(court, {}, 7);
  ASSERT_EQ(a.balls.size(), b.balls.size());
  for (size_t i = 0; i < a.balls.size(); ++i) {
    EXPECT_EQ(a.balls[i].center_in_field, b.balls[i].center_in_field);
  }
  EXPECT_EQ(a.robot.pose.position, b.robot.pose.position);
  EXPECT_EQ(a.effects.brightness_gain, b.effects.brightness_gain);
  const CourtScene c = make_court_scene(court, {}, 8);
  EXPECT_NE(a.robot.pose.position, c.robot.pose.position);
  EXPECT_NE(a.balls.back().center_in_field, c.balls.back().center_in_field);
}

TEST(CourtScenario, BallsOnTheGroundWithoutOverlapSomeTouching) {
  const TennisCourtSpec court;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const CourtScene scene = make_court_scene(court, {}, seed);
    const auto tennis = of_kind(scene, ObjectKind::tennis_ball);
    EXPECT_GE(tennis.size(), 20u);
    EXPECT_LE(tennis.size(), 60u);
    EXPECT_EQ(of_kind(scene, ObjectKind::reference_ball).size(), 12u);
    int touching = 0;
    for (size_t i = 0; i < scene.balls.size(); ++i) {
      const SceneSphere& a = scene.balls[i];
      EXPECT_DOUBLE_EQ(a.center_in_field.z(), a.radius_m);
      EXPECT_TRUE(court.surround_rect().contains(a.center_in_field.head<2>()));
      // Clear of the robot's footprint.
      const Vec2 p = scene.robot.pose.field_from_robot().inverse() * a.center_in_field.head<2>();
      EXPECT_TRUE(std::abs(p.x()) >= scene.robot.length_m / 2 + a.radius_m ||
                  std::abs(p.y()) >= scene.robot.width_m / 2 + a.radius_m)
          << p.transpose();
      for (size_t j = i + 1; j < scene.balls.size(); ++j) {
        const SceneSphere& b = scene.balls[j];
        const double gap = (a.center_in_field - b.center_in_field).norm() - a.radius_m - b.radius_m;
        EXPECT_GT(gap, 0.0) << i << " and " << j << " overlap";
        if (gap < 0.005) ++touching;
      }
    }
    EXPECT_GE(touching, static_cast<int>(tennis.size()) / 8) << "clusters of touching balls";
    // Some balls lie within 35 cm of the robot.
    int beside_robot = 0;
    for (const SceneSphere* s : tennis) {
      beside_robot += (s->center_in_field.head<2>() - scene.robot.pose.position).norm() < 0.75;
    }
    EXPECT_GE(beside_robot, 3);
  }
}

/// Tennis balls of `scene` whose footprint reaches into the net's (posts included), and whether
/// the robot's footprint does.
std::pair<int, bool> in_the_net(const CourtScene& scene) {
  const FloorBox net = TennisNet::of(TennisCourtSpec{}).value().bounds();
  int balls = 0;
  for (const SceneSphere* s : of_kind(scene, ObjectKind::tennis_ball)) {
    const Vec2 p = s->center_in_field.head<2>();
    balls += std::abs(p.x()) < net.half_size.x() + s->radius_m &&
             std::abs(p.y()) < net.half_size.y() + s->radius_m;
  }
  const RobotBox& r = scene.robot;
  bool robot = false;
  for (const Vec2& corner : {Vec2(1, 1), Vec2(1, -1), Vec2(-1, 1), Vec2(-1, -1)}) {
    const Vec2 p = r.pose.field_from_robot() *
                   Vec2(corner.x() * r.length_m / 2.0, corner.y() * r.width_m / 2.0);
    robot = robot || p.x() * r.pose.position.x() <= 0.0 || std::abs(p.x()) < net.half_size.x();
  }
  return {balls, robot};
}

TEST(CourtScenario, BallsAndTheRobotKeepClearOfTheNet) {
  TennisCourtSpec no_net;
  no_net.net.enabled = false;
  CourtScenarioOptions options;
  options.ball_count = CourtScenarioOptions::kMaxBalls;
  int balls_without_net = 0, robots_without_net = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto [balls, robot] = in_the_net(make_court_scene(TennisCourtSpec{}, options, seed));
    EXPECT_EQ(balls, 0);
    EXPECT_FALSE(robot);
    const auto [free_balls, free_robot] = in_the_net(make_court_scene(no_net, options, seed));
    balls_without_net += free_balls;
    robots_without_net += free_robot;
  }
  // Without the net, balls and the robot do land on the net line: the net keeps them off.
  EXPECT_GT(balls_without_net, 10);
  EXPECT_GE(robots_without_net, 1);
}

// The layouts of the closed loop's harder scenes: every ball but the (up to four) beside the robot
// lies where the layout says, clear of the net, inside the fence.
TEST(CourtScenario, LayoutsPutTheBallsAlongTheNetTheFenceOrAroundThePosts) {
  const TennisCourtSpec court;
  const GroundRect fence = court.surround_rect();
  const std::array<Vec2, 2> posts = TennisNet::of(court)->post_positions();
  const auto near_fence = [&](const Vec2& p) {
    return std::min({p.x() - fence.x_min, fence.x_max - p.x(), p.y() - fence.y_min,
                     fence.y_max - p.y()}) <= 0.20 + 1e-9;
  };
  const auto near_post = [&](const Vec2& p) {
    return (p - posts[0]).norm() <= 0.60 + 1e-9 || (p - posts[1]).norm() <= 0.60 + 1e-9;
  };
  for (const BallLayout layout :
       {BallLayout::along_net, BallLayout::along_fence, BallLayout::net_posts}) {
    CourtScenarioOptions options;
    options.ball_count = 30;
    options.cluster_share = 0.0;
    options.layout = layout;
    const CourtScene scene = make_court_scene(court, options, 3);
    int placed = 0, sides = 0;
    for (const SceneSphere* b : of_kind(scene, ObjectKind::tennis_ball)) {
      const Vec2 p = b->center_in_field.head<2>();
      EXPECT_TRUE(fence.contains(p)) << ball_layout_name(layout);
      const bool where = layout == BallLayout::along_net     ? std::abs(p.x()) <= 0.30 + 1e-9
                         : layout == BallLayout::along_fence ? near_fence(p)
                                                             : near_post(p);
      placed += where ? 1 : 0;
      sides += p.x() > 0.0 ? 1 : 0;
    }
    EXPECT_GE(placed, 26) << ball_layout_name(layout);
    EXPECT_GT(sides, 3) << ball_layout_name(layout);  // both sides of the net
    EXPECT_LT(sides, 27) << ball_layout_name(layout);
  }
  EXPECT_EQ(ball_layout_name(BallLayout::scattered), "scattered");
}

TEST(CourtScenario, BallCountLightingAndNoiseFollowTheOptions) {
  CourtScenarioOptions options;
  options.ball_count = 0;
  options.noise_sigma = 5.0;
  options.brightness_gain = 0.7;
  options.shadow = false;
  CourtScene scene = make_court_scene({}, options, 3);
  EXPECT_TRUE(of_kind(scene, ObjectKind::tennis_ball).empty());
  EXPECT_EQ(scene.effects.noise_sigma, 5.0);
  EXPECT_EQ(scene.effects.brightness_gain, 0.7);
  EXPECT_FALSE(scene.lighting.shadow);
  options.ball_count = CourtScenarioOptions::kMaxBalls;
  options.shadow = true;
  scene = make_court_scene({}, options, 3);
  EXPECT_EQ(of_kind(scene, ObjectKind::tennis_ball).size(), 200u);
  ASSERT_TRUE(scene.lighting.shadow);
  // The band crosses the court: its centre line passes through the court.
  EXPECT_TRUE(TennisCourtSpec{}.court_rect().contains(scene.lighting.shadow->point_in_field));
  EXPECT_EQ(scene.lighting.sun_visibility(scene.lighting.shadow->point_in_field), 0.0);
}

// Over a few dozen scenes every light condition comes up with its own sun and band, some balls
// are worn (paler: less saturated), and with distractors some scenes have leaves or a bottle clear
// of the balls.
TEST(CourtScenario, WeatherWearAndDistractorsVaryBetweenScenes) {
  const TennisCourtSpec court;
  CourtScenarioOptions options;
  options.distractors = true;
  std::map<LightCondition, int> conditions;
  int worn = 0, leafy = 0, bottled = 0;
  const auto saturation = [](const cv::Vec3b& bgr) {
    const int hi = std::max({bgr[0], bgr[1], bgr[2]}), lo = std::min({bgr[0], bgr[1], bgr[2]});
    return static_cast<double>(hi - lo) / hi;
  };
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const CourtScene scene = make_court_scene(court, options, seed);
    EXPECT_EQ(make_court_scene(court, {}, seed).balls.size(), scene.balls.size());
    const Lighting& light = scene.lighting;
    ++conditions[light.condition];
    if (light.condition == LightCondition::overcast) {
      EXPECT_FALSE(light.shadow);
      EXPECT_GE(light.ambient, 0.6);
      EXPECT_LT(scene.effects.brightness_gain, 0.9);
    } else {
      ASSERT_TRUE(light.shadow);
      if (light.condition == LightCondition::hard_shadow) {
        EXPECT_LE(light.shadow->soft_edge_m, 0.06);
        EXPECT_LE(light.ambient, 0.35);
        EXPECT_LT(light.to_sun.z(), std::sin(rad_from_deg(40.0)) + 1e-9);
      }
    }
    for (const SceneSphere* ball : of_kind(scene, ObjectKind::tennis_ball)) {
      if (ball->bgr == kTennisBallBgr) continue;
      ++worn;
      EXPECT_LT(saturation(ball->bgr), saturation(kTennisBallBgr));
    }
    leafy += !scene.leaves.empty();
    for (const FloorBottle& bottle : scene.bottles) {
      ++bottled;
      for (const SceneSphere& ball : scene.balls)
        EXPECT_GT((ball.center_in_field.head<2>() - bottle.center_in_field).norm(),
                  ball.radius_m + bottle.radius_m);
    }
  }
  EXPECT_EQ(conditions.size(), 3u);
  EXPECT_GT(worn, 20);
  EXPECT_GT(leafy, 4);
  EXPECT_LT(leafy, 20);
  EXPECT_GT(bottled, 1);
  EXPECT_LT(bottled, 14);
}

TEST(CourtScenario, LightWearAndDistractorsFollowTheOptions) {
  CourtScenarioOptions options;
  options.light = LightCondition::hard_shadow;
  options.worn_share_max = 0.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const CourtScene scene = make_court_scene({}, options, seed);
    EXPECT_EQ(scene.lighting.condition, LightCondition::hard_shadow);
    EXPECT_TRUE(scene.leaves.empty());  // distractors are off by default
    EXPECT_TRUE(scene.bottles.empty());
    for (const SceneSphere* ball : of_kind(scene, ObjectKind::tennis_ball))
      EXPECT_EQ(ball->bgr, kTennisBallBgr);
  }
  EXPECT_EQ(light_condition_named("overcast"), LightCondition::overcast);
  EXPECT_EQ(light_condition_name(LightCondition::hard_shadow), "hard_shadow");
  EXPECT_FALSE(light_condition_named("dusk"));
}

// Indoor light is asked for, never drawn: a hall's lamps light from above, leave no shadow band,
// and a white balance set for daylight leaves their warmth as a red-up, blue-down cast.
TEST(CourtScenario, IndoorLightIsTopLitWarmAndOnlyWhenAsked) {
  CourtScenarioOptions options;
  options.light = LightCondition::indoor;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const CourtScene scene = make_court_scene({}, options, seed);
    EXPECT_EQ(scene.lighting.condition, LightCondition::indoor);
    EXPECT_FALSE(scene.lighting.shadow);
    EXPECT_NEAR(scene.lighting.to_sun.z(), 1.0, 1e-12);
    EXPECT_LT(scene.effects.channel_gain[0], 1.0);  // blue
    EXPECT_GT(scene.effects.channel_gain[2], 1.0);  // red
    EXPECT_LT(scene.effects.brightness_gain, 0.85 + 1e-12);
    // Random scenes draw no cast.
    EXPECT_EQ(make_court_scene({}, {}, seed).effects.channel_gain, cv::Vec3d(1.0, 1.0, 1.0));
  }
  EXPECT_EQ(light_condition_named("indoor"), LightCondition::indoor);
}

TEST(CourtScenario, SurfacesPaintTheCourtEachItsOwnColourAndChooseTheReferenceColour) {
  std::set<std::array<uchar, 3>> colours;
  for (const CourtSurface surface : {CourtSurface::green, CourtSurface::blue, CourtSurface::red,
                                     CourtSurface::concrete, CourtSurface::wood}) {
    TennisCourtSpec court;
    court.court_bgr = {1, 2, 3};
    set_court_surface(court, surface);
    EXPECT_EQ(court_surface_named(court_surface_name(surface)), surface);
    EXPECT_NE(court.court_bgr, court.surround_bgr);
    colours.insert({court.court_bgr[0], court.court_bgr[1], court.court_bgr[2]});
  }
  EXPECT_EQ(colours.size(), 5u);  // each surface its own paint
  TennisCourtSpec green;
  set_court_surface(green, CourtSurface::green);
  EXPECT_EQ(green.court_bgr, TennisCourtSpec().court_bgr);
  // Orange reference balls but on the floors of orange's hues; the scene draws the court's.
  TennisCourtSpec red;
  set_court_surface(red, CourtSurface::red);
  EXPECT_EQ(red.reference_ball_bgr, kVioletBgr);
  set_court_surface(red, CourtSurface::blue);
  EXPECT_EQ(red.reference_ball_bgr, TennisCourtSpec().reference_ball_bgr);
  set_court_surface(red, CourtSurface::wood);
  for (const SceneSphere& ball : make_court_scene(red, {}, 1).balls) {
    if (ball.kind != ObjectKind::reference_ball) continue;
    EXPECT_EQ(ball.bgr, kVioletBgr);
  }
  EXPECT_FALSE(court_surface_named("grass"));
  // A blue back marker but on a blue court (it is of the court's hues); the robot wears the
  // court's markers.
  for (const CourtSurface surface : {CourtSurface::green, CourtSurface::red, CourtSurface::wood}) {
    set_court_surface(red, surface);
    EXPECT_EQ(red.robot_back_marker_bgr, kBlueMarkerBgr);
  }
  set_court_surface(red, CourtSurface::blue);
  EXPECT_EQ(red.robot_back_marker_bgr, kVioletBgr);
  EXPECT_EQ(red.robot_front_marker_bgr, kPinkMarkerBgr);
  const RobotBox robot = make_court_scene(red, {}, 1).robot;
  EXPECT_EQ(robot.back_marker().bgr, kVioletBgr);
  EXPECT_EQ(robot.front_marker().bgr, kPinkMarkerBgr);
}

TEST(CourtScenario, EveryCameraSeesSixWellSpreadReferenceBalls) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto rendered = render_in_all_cameras(make_court_scene({}, {}, seed));
    const test_support::CourtFixture& court = test_support::shared_court();
    for (size_t c = 0; c < court.rig.cameras.size(); ++c) {
      const CourtCamera& camera = court.rig.cameras[c];
      std::vector<cv::Point2f> near;  // visible and within 20 m: about 1 px in radius or more
      for (const SphereTruth& t : rendered.truth) {
        const SphereViewTruth& v = t.views[c];
        if (t.sphere.kind != ObjectKind::reference_ball || !v.visible) continue;
        if ((t.sphere.center_in_field - camera.center_in_field()).norm() > 20.0) continue;
        near.emplace_back(static_cast<float>(v.center_px->x()),
                          static_cast<float>(v.center_px->y()));
      }
      EXPECT_GE(near.size(), 5u) << "camera " << c;  // six, less one the robot may hide
      if (near.size() < 3) continue;
      std::vector<cv::Point2f> hull;
      cv::convexHull(near, hull);
      const double image_area = camera.camera.width() * camera.camera.height();
      EXPECT_GT(cv::contourArea(hull) / image_area, 0.05) << "camera " << c;
    }
  }
}

TEST(CourtScenario, InvalidOptionsAndScenesAreNamed) {
  CourtScenarioOptions options;
  options.ball_count = -3;
  EXPECT_THROW(make_court_scene({}, options, 1), InputError);
  options.ball_count = 201;
  EXPECT_THROW(make_court_scene({}, options, 1), InputError);
  options = {};
  options.noise_sigma = -1.0;
  EXPECT_THROW(make_court_scene({}, options, 1), InputError);
  options = {};
  options.brightness_gain = 0.0;
  EXPECT_THROW(make_court_scene({}, options, 1), InputError);

  CourtScene scene;
  scene.balls.push_back(
      {ObjectKind::tennis_ball, 0, Vec3(1, 1, 0.01), kTennisBallRadiusM, kTennisBallBgr});
  try {
    scene.validate();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("balls[0]"), std::string::npos) << e.what();
  }
  scene.balls.clear();
  scene.robot.height_m = 0.0;
  EXPECT_THROW(scene.validate(), InputError);
  scene.robot = {};
  scene.lighting.to_sun = Vec3(0, 0, -1);
  EXPECT_THROW(scene.validate(), InputError);
  scene.lighting = {};
  scene.lighting.shadow = ShadowBand{};
  scene.lighting.shadow->width_m = 0.0;
  EXPECT_THROW(scene.validate(), InputError);
  scene.lighting = {};
  scene.leaves.push_back(FloorLeaf{});
  scene.leaves[0].axis = Vec2(1, 1);
  EXPECT_THROW(scene.validate(), InputError);
  scene.leaves.clear();
  scene.bottles.push_back(FloorBottle{});
  scene.bottles[0].radius_m = -0.03;
  try {
    scene.validate();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bottles[0]"), std::string::npos) << e.what();
  }
  options = {};
  options.worn_share_max = 1.5;
  EXPECT_THROW(make_court_scene({}, options, 1), InputError);
}

}  // namespace
}  // namespace ballsight::sim
