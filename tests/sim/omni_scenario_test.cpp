#include "ballsight/sim/omni_scenario.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/msl_field.hpp"
#include "ballsight/sim/omni_renderer.hpp"
#include "ballsight/sim/omni_truth_json.hpp"

namespace ballsight::sim {
namespace {

// Every frame of a scenario as the bytes the command line writes: PNG and truth JSON.
std::vector<std::pair<std::vector<uchar>, std::string>> render_files(
    const OmniScenarioOptions& options) {
  const OmniScenario scenario = make_omni_scenario(options);
  const OmniRenderer renderer(scenario.rig);
  std::vector<std::pair<std::vector<uchar>, std::string>> files;
  for (const OmniScene& scene : scenario.scenes) {
    const OmniFrame frame = renderer.render(scene);
    std::vector<uchar> png;
    EXPECT_TRUE(cv::imencode(".png", frame.bgr, png));
    files.emplace_back(std::move(png), omni_truth_json_text(frame.truth));
  }
  return files;
}

std::string error_of(const auto& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(OmniScenario, SameSeedSameBytesDifferentSeedDifferentScene) {
  OmniScenarioOptions options;
  options.seed = 42;
  options.frames = 3;
  options.effects = {1.1, 0.8, 2.0};  // the noise is seeded too
  const auto first = render_files(options);
  const auto again = render_files(options);
  ASSERT_EQ(first.size(), 3u);
  EXPECT_EQ(first, again);
  options.seed = 43;
  const auto other = render_files(options);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_NE(first[i].first, other[i].first) << "frame " << i;
    EXPECT_NE(first[i].second, other[i].second) << "frame " << i;
  }
}

TEST(OmniScenario, DrawsAMisalignedRigRobotsOnTheFieldAndBallsInRange) {
  const MslField field;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    OmniScenarioOptions options;
    options.seed = seed;
    options.frames = 5;
    const OmniScenario scenario = make_omni_scenario(options);
    // Misaligned like the paper's robot: 1-2 deg tilt, principal point 3-7 px off centre.
    EXPECT_GE(scenario.rig.tilt_deg, 1.0);
    EXPECT_LE(scenario.rig.tilt_deg, 2.0);
    EXPECT_GE(scenario.rig.center_offset_px.norm(), 3.0);
    EXPECT_LE(scenario.rig.center_offset_px.norm(), 7.0);
    ASSERT_EQ(scenario.scenes.size(), 5u);
    EXPECT_EQ(scenario.scenes[0].markers.size(), 36u * 9u);  // the calibration frame
    EXPECT_FALSE(scenario.scenes[0].ball);
    for (std::size_t i = 1; i < scenario.scenes.size(); ++i) {
      const OmniScene& scene = scenario.scenes[i];
      EXPECT_NO_THROW(scene.validate());
      EXPECT_TRUE(scene.markers.empty());
      ASSERT_TRUE(scene.ball);
      const Vec2& robot = scene.robot_pose.position;
      EXPECT_TRUE(robot.x() >= 0.0 && robot.x() <= 8.0 && robot.y() >= 0.0 && robot.y() <= 12.0);
      const double distance = (scene.ball->position_in_field - robot).norm();
      EXPECT_GE(distance, 0.5);
      EXPECT_LE(distance, 5.0);
      EXPECT_TRUE(field.on_carpet(scene.ball->position_in_field));
    }
  }
}

TEST(OmniScenario, OverridingTheMisalignmentKeepsTheRestOfTheScenario) {
  OmniScenarioOptions options;
  options.seed = 9;
  const OmniScenario drawn = make_omni_scenario(options);
  options.tilt_deg = 0.0;
  options.center_offset_px = Vec2(10.0, -2.0);
  options.calibration_frame = false;
  const OmniScenario set = make_omni_scenario(options);
  EXPECT_EQ(set.rig.tilt_deg, 0.0);
  EXPECT_EQ(set.rig.center_offset_px, Vec2(10.0, -2.0));
  EXPECT_EQ(set.rig.tilt_azimuth_deg, drawn.rig.tilt_azimuth_deg);
  for (std::size_t i = 0; i < set.scenes.size(); ++i) {
    EXPECT_EQ(set.scenes[i].robot_pose.position, drawn.scenes[i].robot_pose.position);
  }
  EXPECT_TRUE(set.scenes[0].ball);  // no calibration frame: a ball from frame 0 on
}

TEST(OmniScenario, RejectsInvalidOptionsNamingThem) {
  OmniScenarioOptions options;
  options.frames = -1;
  EXPECT_NE(error_of([&] { make_omni_scenario(options); }).find("frames"), std::string::npos);
  options = {};
  options.tilt_deg = 45.0;
  EXPECT_NE(error_of([&] { make_omni_scenario(options); }).find("tilt_deg"), std::string::npos);
  options = {};
  options.center_offset_px = Vec2(60.0, 0.0);
  EXPECT_NE(error_of([&] { make_omni_scenario(options); }).find("center_offset_px"),
            std::string::npos);
  options = {};
  options.effects.noise_sigma = -1.0;
  EXPECT_NE(error_of([&] { make_omni_scenario(options); }).find("noise"), std::string::npos);
  options = {};
  options.ball_max_distance_m = 0.45;
  EXPECT_NE(error_of([&] { make_omni_scenario(options); }).find("ball_max_distance_m"),
            std::string::npos);
}

TEST(OmniScene, ValidateNamesTheBadField) {
  OmniScene scene;
  scene.robot_pose = {{4.0, 6.0}, 0.0};
  EXPECT_EQ(error_of([&] { scene.validate(); }), "no error");
  scene.ball = OmniBall{{4.2, 6.0}};
  EXPECT_NE(error_of([&] { scene.validate(); }).find("scene.ball.position_in_field"),
            std::string::npos);
  scene.ball = OmniBall{{5.0, 6.0}, -0.1};
  EXPECT_NE(error_of([&] { scene.validate(); }).find("scene.ball.radius_m"), std::string::npos);
  scene.ball.reset();
  scene.markers = {{1, {5.0, 6.0}, 0.05}, {1, {6.0, 6.0}, 0.05}};
  EXPECT_NE(error_of([&] { scene.validate(); }).find("scene.markers[1].id"), std::string::npos);
  scene.markers = {{1, {5.0, 6.0}, 0.0}};
  EXPECT_NE(error_of([&] { scene.validate(); }).find("scene.markers[0].radius_m"),
            std::string::npos);
  scene.markers.clear();
  scene.robot_pose.heading_rad = std::nan("");
  EXPECT_NE(error_of([&] { scene.validate(); }).find("scene.robot_pose"), std::string::npos);
  scene.robot_pose.heading_rad = 0.0;
  scene.rig.focal_px = -1.0;
  EXPECT_NE(error_of([&] { scene.validate(); }).find("focal_px"), std::string::npos);
}

TEST(MarkerLayout, FollowsTableIAndKeepsNeighboursApart) {
  const Pose2D robot{{3.0, 4.0}, 0.7};
  const MarkerLayout layout;
  const std::vector<FloorMarker> markers = calibration_markers(robot, layout);
  ASSERT_EQ(markers.size(), 36u * 9u);
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const FloorMarker& m = markers[i];
    EXPECT_EQ(m.id, static_cast<int>(i));
    const Vec2 p = robot_from_field_point(robot, m.position_in_field);
    EXPECT_NEAR(p.norm(), 0.6 + 0.5 * (m.id % 9), 1e-9);
    EXPECT_NEAR(wrap_deg_180(polar_from_cartesian(p).theta_deg - 10.0 * (m.id / 9)), 0.0, 1e-9);
    if (m.id % 9 > 0) {
      EXPECT_GE(m.radius_m, markers[i - 1].radius_m);  // grows outwards
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double gap = (m.position_in_field - markers[j].position_in_field).norm() - m.radius_m -
                         markers[j].radius_m;
      EXPECT_GT(gap, 0.1 * std::min(m.radius_m, markers[j].radius_m)) << i << " vs " << j;
    }
  }
  MarkerLayout bad;
  bad.fill = 1.2;
  EXPECT_NE(error_of([&] { calibration_markers(robot, bad); }).find("marker layout.fill"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight::sim
