#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_scenario.hpp"
#include "ballsight/sim/silhouette.hpp"
#include "omni_blobs.hpp"
#include "polygon_area.hpp"

namespace ballsight::sim {
namespace {

using test_support::polygon_area;

OmniRigParams misaligned_rig() {
  OmniRigParams rig;
  rig.tilt_deg = 1.5;
  rig.tilt_azimuth_deg = 40.0;
  rig.center_offset_px = {4.0, -3.0};
  return rig;
}

TEST(OmniRender, BallBlobCentroidMatchesTheAnalyticSilhouette) {
  const OmniRenderer renderer(misaligned_rig());
  constexpr std::uint64_t kSeed = 2024;
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double distances_m[] = {0.6, 0.8, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0};
  double worst_px = 0.0;
  for (int trial = 0; trial < 36; ++trial) {
    SCOPED_TRACE(testing::Message() << "seed " << kSeed << " trial " << trial);
    OmniScene scene;
    scene.rig = renderer.rig().params();
    scene.robot_pose = {{1.0 + 6.0 * unit(rng), 1.0 + 10.0 * unit(rng)}, 2.0 * kPi * unit(rng)};
    const double distance = distances_m[trial % 9];
    const Vec2 p_in_robot = robot_point_from_bearing(360.0 * unit(rng), distance);
    scene.ball = OmniBall{field_from_robot_point(scene.robot_pose, p_in_robot)};
    const OmniFrame frame = renderer.render(scene);

    ASSERT_TRUE(frame.truth.ball && frame.truth.ball->visible);
    const std::optional<test::Blob> blob = test::mask_blob(test::ball_mask(frame.bgr));
    ASSERT_TRUE(blob);
    const double error = (blob->centroid - *frame.truth.ball->silhouette_centroid_px).norm();
    EXPECT_LT(error, 0.5) << distance << " m";
    worst_px = std::max(worst_px, error);

    // The blob is the ball, not a smaller or larger shape with the same centre: its area matches
    // the projected silhouette's to within the pixels along its outline.
    const Vec3 center(p_in_robot.x(), p_in_robot.y(), scene.ball->radius_m);
    const auto outline = project_outline(
        renderer.rig(),
        sphere_silhouette(renderer.rig().robot_from_camera().translation, center, 0.11, 256));
    ASSERT_TRUE(outline);
    const double area = polygon_area(*outline);
    EXPECT_NEAR(blob->area_px, area, 0.1 * area + 3.0) << distance << " m";
  }
  RecordProperty("worst_ball_centroid_error_px", std::to_string(worst_px));
}

TEST(OmniRender, MarkerBlobsSitOnTheirTruePixels) {
  constexpr std::uint64_t kSeed = 77;
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst_px = 0.0;
  for (int trial = 0; trial < 8; ++trial) {
    SCOPED_TRACE(testing::Message() << "seed " << kSeed << " trial " << trial);
    OmniRigParams rig;  // misaligned as the scenarios' default rigs
    rig.tilt_deg = 2.0 * unit(rng);
    rig.tilt_azimuth_deg = 360.0 * unit(rng);
    rig.center_offset_px = 7.0 * unit(rng) * Vec2(std::cos(7.0 * trial), std::sin(7.0 * trial));
    const OmniRenderer renderer(rig);
    OmniScene scene;
    scene.rig = rig;
    scene.robot_pose = {{8.0 * unit(rng), 12.0 * unit(rng)}, 2.0 * kPi * unit(rng)};
    const cv::Mat bare = renderer.render(scene).bgr;
    scene.markers = calibration_markers(scene.robot_pose);
    const OmniFrame frame = renderer.render(scene);
    const cv::Mat covered = test::coverage(frame.bgr, bare, scene.palette.marker_bgr);

    // Detectable: thresholded at half coverage, one blob per marker (neighbours never merge),
    // each at least 3 px across in both image directions.
    cv::Mat mask;
    cv::threshold(covered, mask, 0.5, 255, cv::THRESH_BINARY);
    mask.convertTo(mask, CV_8U);
    const std::vector<test::Blob> blobs = test::mask_blobs(mask);
    ASSERT_EQ(blobs.size(), scene.markers.size());
    for (const test::Blob& blob : blobs) EXPECT_GE(std::min(blob.box.width, blob.box.height), 3);

    // Each covered pixel belongs to the marker nearest its floor point; the coverage-weighted
    // centroid of a marker's pixels is its image centre.
    const std::vector<OmniMarkerTruth>& truth = frame.truth.markers;
    std::vector<Eigen::Vector3d> sums(truth.size(), Eigen::Vector3d::Zero());  // a, a x, a y
    for (int y = 0; y < covered.rows; ++y) {
      for (int x = 0; x < covered.cols; ++x) {
        const double a = covered.at<float>(y, x);
        const std::optional<Vec2> ground = renderer.rig().ground_from_pixel({x, y});
        if (a <= 0.0 || !ground) continue;
        const auto nearest =
            std::min_element(truth.begin(), truth.end(), [&](const auto& p, const auto& q) {
              return (p.position_in_robot - *ground).norm() <
                     (q.position_in_robot - *ground).norm();
            });
        sums[nearest - truth.begin()] += a * Eigen::Vector3d(1.0, x, y);
      }
    }
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const OmniMarkerTruth& m = truth[k];
      SCOPED_TRACE(testing::Message() << "marker " << m.id << " at " << m.range.distance_m << " m");
      ASSERT_TRUE(m.visible);  // the layout lies well inside the mirror
      ASSERT_GT(sums[k][0], 1.0);
      const Vec2 centroid = sums[k].tail<2>() / sums[k][0];
      const double error = (centroid - *m.pixel).norm();
      EXPECT_LT(error, 0.5);
      EXPECT_LT((centroid - *m.silhouette_centroid_px).norm(), 0.5);
      worst_px = std::max(worst_px, error);
    }
  }
  RecordProperty("worst_marker_centroid_error_px", std::to_string(worst_px));
}

TEST(OmniRender, ShowsTheFieldTheRobotSees) {
  const OmniRenderer renderer{OmniRigParams{}};
  OmniScene scene;
  scene.robot_pose = {{4.0, 3.0}, rad_from_deg(90.0)};  // facing the halfway line, 3 m ahead
  const OmniFrame frame = renderer.render(scene);
  const OmniRig& rig = renderer.rig();
  const auto colour_of = [&](const Vec2& p_in_field) {
    const Vec2 p = robot_from_field_point(scene.robot_pose, p_in_field);
    const std::optional<Vec2> pixel = rig.pixel_from_point({p.x(), p.y(), 0.0});
    EXPECT_TRUE(pixel);
    return frame.bgr.at<cv::Vec3b>(static_cast<int>(std::lround(pixel->y())),
                                   static_cast<int>(std::lround(pixel->x())));
  };
  EXPECT_EQ(colour_of({4.0, 6.0}), scene.field.line_bgr);  // halfway line, in the image's top
  EXPECT_EQ(colour_of({4.0, 1.5}), scene.field.line_bgr);  // penalty area's front line
  const cv::Vec3b carpet = colour_of({5.0, 4.0});
  EXPECT_GT(carpet[1], carpet[0] + 60);  // green
  EXPECT_GT(carpet[1], carpet[2] + 60);
  EXPECT_EQ(colour_of({-1.6, 3.0}), scene.field.floor_bgr);  // beyond the carpet
  // The robot's body masks the centre; outside the mirror circle is black.
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(240, 320), scene.palette.robot_body_bgr);
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(5, 5), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(240, 639), cv::Vec3b(0, 0, 0));
  // The halfway line is imaged above the centre (robot forward = image up).
  const Vec2 ahead = *rig.pixel_from_point({3.0, 0.0, 0.0});
  EXPECT_LT(ahead.y(), 240.0 - 100.0);
}

TEST(OmniRender, ObjectsSeeAboveTheHorizonAsBackground) {
  OmniRigParams params;
  params.mirror_radius_px = 300.0;  // wider than the horizon circle (256 px)
  const OmniRenderer renderer(params);
  OmniScene scene;
  scene.rig = params;
  scene.robot_pose = {{4.0, 6.0}, 0.0};
  const OmniFrame frame = renderer.render(scene);
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(240, static_cast<int>(319.5 + 280.0)),
            scene.palette.background_bgr);
}

TEST(OmniRender, RejectsASceneForAnotherRigOrAnInvalidScene) {
  const OmniRenderer renderer{OmniRigParams{}};
  OmniScene scene;
  scene.robot_pose = {{4.0, 6.0}, 0.0};
  scene.rig.tilt_deg = 1.0;
  EXPECT_THROW(renderer.render(scene), InputError);
  scene.rig = {};
  scene.rig.mirror = default_mirror(MirrorKind::kSphere);  // the same rig but its mirror
  EXPECT_THROW(renderer.render(scene), InputError);
  scene.rig = {};
  scene.ball = OmniBall{{4.1, 6.0}};  // under the robot
  EXPECT_THROW(renderer.render(scene), InputError);
}

TEST(OmniRender, EffectsAreSeededAndChangeTheImage) {
  OmniScene scene;
  scene.robot_pose = {{4.0, 6.0}, 0.3};
  scene.ball = OmniBall{{5.0, 7.0}};
  const cv::Mat clean = render_omni_scene(scene).bgr;
  scene.effects = {1.2, 1.0, 4.0};
  scene.noise_seed = 17;
  const cv::Mat a = render_omni_scene(scene).bgr;
  const cv::Mat b = render_omni_scene(scene).bgr;
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, clean, cv::NORM_L1) / static_cast<double>(clean.total()), 3.0);
  scene.noise_seed = 18;
  EXPECT_GT(cv::norm(render_omni_scene(scene).bgr, a, cv::NORM_L1), 0.0);
}

}  // namespace
}  // namespace ballsight::sim
