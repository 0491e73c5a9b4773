// Obstacles found by the court pipeline (detect/court_foreground.hpp, world/floor_obstacles.hpp)
// on the simulated court: a person and a bag are put on the floor where they stand, with their
// footprint, by the four corner cameras; the robot, the balls and the empty court are not
// obstacles.
#include <gtest/gtest.h>

#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"

namespace ballsight {
namespace {

struct Court {
  sim::CourtRig rig = sim::make_court_rig({}, {}, 7);
  std::vector<sim::CourtRenderer> renderers;
  std::vector<FieldCamera> cameras;

  Court() {
    for (const sim::CourtCamera& c : rig.cameras) {
      renderers.emplace_back(c, rig.court);
      cameras.push_back({c.camera, c.camera_from_field});
    }
  }

  /// The world model of `scene` from a pipeline that knows the empty court.
  WorldModel world(const sim::CourtScene& scene) const {
    BallsightPipelineOptions options;
    options.world.obstacles.net = NetPanel{};  // the simulator's court
    FrameSet frames;
    for (std::size_t c = 0; c < renderers.size(); ++c) {
      cv::Mat empty = renderers[c].lit_background(scene.lighting, scene.leaves);
      sim::apply_image_effects(empty, scene.effects, 1000 + c);
      options.empty_court.push_back(empty);
      CameraFrame frame;
      frame.camera = c;
      frame.image = renderers[c].render(scene, 5 + c).bgr;
      frames.cameras.push_back(frame);
    }
    return make_ballsight_pipeline(cameras, options)->process(frames).world;
  }
};

const Court& court() {
  static const Court c;
  return c;
}

sim::CourtScene scene_with_obstacles(std::uint64_t seed) {
  sim::CourtScenarioOptions options;
  options.ball_count = 40;
  options.obstacles.people = 1;
  options.obstacles.bags = 1;
  return sim::make_court_scene(court().rig.court, options, seed);
}

TEST(FloorObstacles, APersonAndABagWhereTheyStand) {
  for (const std::uint64_t seed : {1, 2, 3, 4, 5, 6}) {
    const sim::CourtScene scene = scene_with_obstacles(seed);
    const WorldModel world = court().world(scene);
    ASSERT_EQ(world.obstacles.size(), 2u) << "seed " << seed;
    for (const sim::CourtObstacle& truth : scene.obstacles) {
      const auto found = std::min_element(world.obstacles.begin(), world.obstacles.end(),
                                          [&](const FloorObstacle& a, const FloorObstacle& b) {
                                            return (a.center_m - truth.pose.position).norm() <
                                                   (b.center_m - truth.pose.position).norm();
                                          });
      const double reach =
          truth.kind == sim::ObstacleKind::person ? truth.half_size.x() : truth.half_size.norm();
      EXPECT_LT((found->center_m - truth.pose.position).norm(), 0.25)
          << "seed " << seed << " " << sim::obstacle_kind_name(truth.kind);
      // The footprint holds the obstacle's and is not much larger.
      EXPECT_GE(found->radius_m, reach) << "seed " << seed;
      EXPECT_LE(found->radius_m, reach + 0.3) << "seed " << seed;
      EXPECT_GE(found->cameras.size(), 2u);
    }
    // The balls are found as well as without them (a ball may hide behind a person).
    sim::CourtScene plain = scene;
    plain.obstacles.clear();
    EXPECT_GE(world.balls.size() + 2, court().world(plain).balls.size()) << "seed " << seed;
  }
}

TEST(FloorObstacles, NoneOnACourtWithoutThem) {
  sim::CourtScenarioOptions options;
  options.ball_count = 60;
  for (std::uint64_t seed = 4; seed < 10; ++seed) {
    const WorldModel world = court().world(sim::make_court_scene(court().rig.court, options, seed));
    EXPECT_TRUE(world.obstacles.empty())
        << "seed " << seed << ": " << world.obstacles.size() << " obstacles, the first at "
        << world.obstacles.front().center_m.transpose();
    ASSERT_TRUE(world.robot.has_value());
  }
}

}  // namespace
}  // namespace ballsight
