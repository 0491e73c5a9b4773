#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/sim/court_background.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/court_truth.hpp"
#include "ballsight/sim/tennis_net.hpp"
#include "sim/court_test_support.hpp"

namespace ballsight::sim {
namespace {

using test_support::clean_scenario;
using test_support::render_in_all_cameras;
using test_support::shared_court;
using test_support::shared_court_without_net;

SceneSphere tennis_ball_at(double x, double y) {
  return {ObjectKind::tennis_ball, 0, Vec3(x, y, kTennisBallRadiusM), kTennisBallRadiusM,
          kTennisBallBgr};
}

/// One ball and the robot far from it, no noise.
CourtScene one_ball_scene(const SceneSphere& ball) {
  CourtScene scene;
  scene.robot.pose = {{-9.0, -3.0}, 0.0};
  scene.effects.noise_sigma = 0.0;
  scene.balls.push_back(ball);
  return scene;
}

/// A camera 60 cm above the court, 6 m in front of the net, looking across it.
CourtCamera low_camera() {
  PinholeParams p;
  p.width = 800;
  p.height = 600;
  p.fx = p.fy = 400.0;
  p.cx = 399.5;
  p.cy = 299.5;
  const Vec3 eye(6.0, 0.5, 0.6);
  return {PinholeCamera(p), camera_from_field_looking_at(eye, Vec3(0.0, 2.5, 0.5), 0.0)};
}

TEST(CourtNet, BallJustBehindTheNetIsHiddenFromTheCamerasAcrossIt) {
  // 40 cm behind the net as the cameras at +x (0 and 1) see it: their rays to it pass the net
  // line below 20 cm.
  const CourtScene scene = one_ball_scene(tennis_ball_at(-0.4, 1.0));
  const auto with_net = render_in_all_cameras(shared_court(), scene);
  const auto without = render_in_all_cameras(shared_court_without_net(), scene);
  for (size_t c = 0; c < 4; ++c) {
    SCOPED_TRACE("camera " + std::to_string(c));
    const SphereViewTruth& view = with_net.truth[0].views[c];
    const bool across = shared_court().rig.cameras[c].center_in_field().x() > 0.0;
    EXPECT_TRUE(view.in_image);
    EXPECT_EQ(view.hidden_by_net, across);
    EXPECT_EQ(view.visible, !across);
    EXPECT_DOUBLE_EQ(view.visible_fraction, across ? 0.0 : 1.0);
    EXPECT_EQ(cv::countNonZero(with_net.renders[c].object_ids == 0) > 0, !across);
    // Without the net every camera sees it whole.
    const SphereViewTruth& open = without.truth[0].views[c];
    EXPECT_TRUE(open.visible);
    EXPECT_FALSE(open.hidden_by_net);
    EXPECT_DOUBLE_EQ(open.visible_fraction, 1.0);
  }
}

TEST(CourtNet, LowCameraLosesABallThatTheHighCamerasSeeOverTheNet) {
  // 7 m behind the net: the corner cameras (4-6 m up, 18 m before the net) look over the cord,
  // the low camera does not.
  const SceneSphere ball = tennis_ball_at(-7.0, 0.5);
  const CourtScene scene = one_ball_scene(ball);
  TennisCourtSpec no_net;
  no_net.net.enabled = false;
  const CourtCamera low = low_camera();
  const SphereViewTruth hidden = sphere_view_truth(
      low, ball, CourtRenderer(low, TennisCourtSpec{}).render(scene, 0).coverage[0]);
  EXPECT_TRUE(hidden.in_image);
  EXPECT_TRUE(hidden.hidden_by_net);
  EXPECT_FALSE(hidden.visible);
  const SphereViewTruth open =
      sphere_view_truth(low, ball, CourtRenderer(low, no_net).render(scene, 0).coverage[0]);
  EXPECT_TRUE(open.visible);
  EXPECT_FALSE(open.hidden_by_net);
  const auto rig_views = render_in_all_cameras(scene);
  for (const size_t c : {0u, 1u}) {
    EXPECT_TRUE(rig_views.truth[0].views[c].visible) << "camera " << c;
    EXPECT_DOUBLE_EQ(rig_views.truth[0].views[c].visible_fraction, 1.0) << "camera " << c;
  }
}

/// Colour the renderer should give a pixel wholly on a surface of `albedo` at `p` with `normal`,
/// seen from `eye` (sun shading and haze as for the floor).
cv::Vec3f expected_colour(const cv::Vec3b& albedo, const Lighting& lighting, const Vec3& normal,
                          const Vec3& p, const Vec3& eye) {
  const float haze = haze_share((p - eye).norm());
  const auto light = static_cast<float>(lighting.irradiance(normal, p));
  return cv::Vec3f(albedo[0], albedo[1], albedo[2]) * ((1.0f - haze) * light) +
         kSkyHorizonBgr * haze;
}

/// The pixel nearest to where `p` projects has, channel by channel, a colour within [lo, hi]
/// (+- 1 for rounding) and shows no object.
void expect_colour_at(const CourtCamera& camera, const CourtRender& render, const Vec3& p,
                      const cv::Vec3f& lo, const cv::Vec3f& hi, const char* what) {
  const auto pixel = camera.camera.project(camera.camera_from_field * p);
  ASSERT_TRUE(pixel && camera.camera.in_image(*pixel)) << what;
  const int x = static_cast<int>(std::lround(pixel->x())),
            y = static_cast<int>(std::lround(pixel->y()));
  const cv::Vec3b got = render.bgr.at<cv::Vec3b>(y, x);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GE(got[k], lo[k] - 1.0) << what << " channel " << k << " at " << x << ", " << y;
    EXPECT_LE(got[k], hi[k] + 1.0) << what << " channel " << k << " at " << x << ", " << y;
  }
  EXPECT_EQ(render.object_ids.at<int>(y, x), -1) << what;
}

void expect_colour_at(const CourtCamera& camera, const CourtRender& render, const Vec3& p,
                      const cv::Vec3f& expected, const char* what) {
  expect_colour_at(camera, render, p, expected, expected, what);
}

TEST(CourtNet, PixelsOnTheNetShowItLitByTheSun) {
  const TennisCourtSpec court;
  const TennisNet net = TennisNet::of(court).value();
  CourtScene scene = one_ball_scene(tennis_ball_at(8.0, -3.0));
  scene.lighting.to_sun = Vec3(0.8, 0.2, 0.56).normalized();  // low, on the +x side
  const CourtCamera low = low_camera();
  const Vec3 eye = low.center_in_field();
  const CourtRender render = CourtRenderer(low, court).render(scene, 0);
  const Vec3 facing = Vec3::UnitX();  // the side the camera and the sun are on
  const Vec3 mesh(0.0, 2.5, 0.4);
  expect_colour_at(low, render, mesh,
                   expected_colour(court.net.mesh_bgr, scene.lighting, facing, mesh, eye), "mesh");
  const Vec3 band(0.0, 2.5, net.top_height_m(2.5) - court.net.band_depth_m / 2.0);
  expect_colour_at(low, render, band,
                   expected_colour(court.net.band_bgr, scene.lighting, facing, band, eye), "band");
  // The post's face towards the camera. The pixel nearest to it and its samples see the post up
  // to 0.8 px (of 1.9 px, its half width) aside, where its normal turns by up to 25 degrees.
  const Vec2 post = net.post_positions()[1];
  const double towards = std::atan2(eye.y() - post.y(), eye.x() - post.x());
  const auto post_normal = [&](double turn_deg) {
    const double a = towards + rad_from_deg(turn_deg);
    return Vec3(std::cos(a), std::sin(a), 0.0);
  };
  const Vec3 on_post = Vec3(post.x(), post.y(), 0.5) + court.net.post_radius_m * post_normal(0.0);
  const auto post_colour = [&](double turn_deg) {
    return expected_colour(court.net.post_bgr, scene.lighting, post_normal(turn_deg), on_post, eye);
  };
  cv::Vec3f lo = post_colour(0.0), hi = lo;
  for (const double turn : {-25.0, 25.0}) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], post_colour(turn)[k]);
      hi[k] = std::max(hi[k], post_colour(turn)[k]);
    }
  }
  expect_colour_at(low, render, on_post, lo, hi, "post");
  // From the far side (camera 2, at -x) the net's face is in its own shade: ambient light only.
  const CourtCamera& far = shared_court().rig.cameras[2];
  const CourtRender far_render = shared_court().renderers[2].render(scene, 0);
  expect_colour_at(
      far, far_render, mesh,
      expected_colour(court.net.mesh_bgr, scene.lighting, -facing, mesh, far.center_in_field()),
      "mesh from behind");
  EXPECT_NEAR(scene.lighting.irradiance(-facing, mesh), scene.lighting.ambient, 1e-12);
}

/// Pixels of the net and its posts, from their outlines projected through the lens.
cv::Mat1b net_mask(const CourtCamera& camera, const TennisNet& net) {
  cv::Mat1b mask(camera.camera.height(), camera.camera.width(), uchar{0});
  const auto pixel = [&](const Vec3& p) {
    const Vec2 px = camera.camera.project(camera.camera_from_field * p).value();
    return cv::Point(static_cast<int>(std::lround(px.x())), static_cast<int>(std::lround(px.y())));
  };
  constexpr int kSteps = 64;
  const double post_y = net.post_positions()[1].y();
  std::vector<cv::Point> outline;
  for (int i = 0; i <= kSteps; ++i)
    outline.push_back(pixel({0.0, -post_y + 2 * post_y * i / kSteps, 0.0}));
  for (int i = kSteps; i >= 0; --i) {
    const double y = -post_y + 2 * post_y * i / kSteps;
    outline.push_back(pixel({0.0, y, net.top_height_m(y)}));
  }
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{outline}, 255);
  for (const Vec2& post : net.post_positions()) {
    std::vector<cv::Point> cylinder, hull;
    for (int i = 0; i < 32; ++i) {
      const double a = 2 * kPi * i / 32;
      const Vec2 rim = post + net.spec().post_radius_m * Vec2(std::cos(a), std::sin(a));
      cylinder.push_back(pixel({rim.x(), rim.y(), 0.0}));
      cylinder.push_back(pixel({rim.x(), rim.y(), net.spec().post_height_m}));
    }
    cv::convexHull(cylinder, hull);
    cv::fillConvexPoly(mask, hull, 255);
  }
  return mask;
}

TEST(CourtNet, NetOnAndOffImagesDifferOnlyWhereTheNetIs) {
  const TennisNet net = TennisNet::of(TennisCourtSpec{}).value();
  const CourtScene scene = make_court_scene(TennisCourtSpec{}, clean_scenario(), 3);
  for (const size_t c : {0u, 2u}) {
    SCOPED_TRACE("camera " + std::to_string(c));
    const CourtCamera& camera = shared_court().rig.cameras[c];
    cv::Mat diff, differ;
    cv::absdiff(shared_court().renderers[c].render(scene, 0).bgr,
                shared_court_without_net().renderers[c].render(scene, 0).bgr, diff);
    cv::transform(diff, differ, cv::Matx13f(1, 1, 1));
    const cv::Mat changed = differ > 0;
    const cv::Mat1b mask = net_mask(camera, net);
    cv::Mat1b near_net, inside;
    cv::dilate(mask, near_net, cv::Mat(), cv::Point(-1, -1), 2);  // anti-aliased edge pixels
    cv::erode(mask, inside, cv::Mat(), cv::Point(-1, -1), 2);
    EXPECT_EQ(cv::countNonZero(changed & ~near_net), 0) << "changed away from the net";
    const int interior = cv::countNonZero(inside);
    EXPECT_GT(interior, 10000);
    EXPECT_GT(cv::countNonZero(changed & inside), 0.99 * interior) << "of " << interior;
  }
}

TEST(CourtNet, ScenariosHideBallsBehindTheNetOnlyFromAcrossIt) {
  int hidden_views = 0;
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("scene seed " + std::to_string(seed));
    const auto rendered =
        render_in_all_cameras(make_court_scene(TennisCourtSpec{}, clean_scenario(), seed));
    for (const SphereTruth& t : rendered.truth) {
      for (size_t c = 0; c < t.views.size(); ++c) {
        const SphereViewTruth& v = t.views[c];
        if (!v.hidden_by_net) continue;
        ++hidden_views;
        const double camera_x = shared_court().rig.cameras[c].center_in_field().x();
        EXPECT_LT(camera_x * t.sphere.center_in_field.x(), 0.0) << "on the camera's side";
        EXPECT_LE(v.visible_fraction, 0.5);
        EXPECT_FALSE(v.visible && v.visible_fraction > 0.5);
      }
    }
  }
  EXPECT_GE(hidden_views, 6);
}

}  // namespace
}  // namespace ballsight::sim
