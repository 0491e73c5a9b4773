// The closed loop end to end on a court laid out for it: a ball against the net, one in a corner
// of the fence, and a person standing between the robot and the third ball. ballsight's service
// (the cameras see the person against the empty court) and the robot over the loopback link
// collect all three in time, and the recorded truth shows the body never came near the person.
//
// Not asserted: no contact at all. At the ball against the net the robot touches the net for one
// tick (0.1 s): the ball drops out of the world model as the mouth reaches it, the route turns to
// the next ball, and the robot turns on the spot in the net's lane (issue 43, left open).
//
// The run is recorded as `eval loop --record-mcap` records it: every update, in simulated time
// the court waiting for the recorder rather than dropping one.
#include <gtest/gtest.h>

#include "ballsight/eval/loop_eval.hpp"
#include "ballsight/net/loopback_robot_link.hpp"
#include "ballsight/record/mcap_info.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/robot_motion.hpp"
#include "temp_dir.hpp"

namespace ballsight::test {
namespace {

sim::SceneSphere tennis_ball(int id, const Vec2& p) {
  sim::SceneSphere b;
  b.id = id;
  b.center_in_field = Vec3(p.x(), p.y(), sim::kTennisBallRadiusM);
  return b;
}

TEST(LoopEndToEnd, ABallAgainstTheNetOneInACornerAndOneBehindAPersonAllCollected) {
  eval::LoopScene scene;
  scene.seed = 7;
  scene.balls = 3;
  scene.arrange = [](sim::CourtScene& s) {
    std::erase_if(s.balls,
                  [](const sim::SceneSphere& b) { return b.kind == sim::ObjectKind::tennis_ball; });
    const sim::TennisCourtSpec court;
    const double r = sim::kTennisBallRadiusM;
    // Against the net on the robot's side; in a corner, 10 cm from both sides of the fence; and
    // beyond a person standing in the way.
    s.balls.push_back(tennis_ball(0, Vec2(court.net.post_radius_m + r + 0.005, -3.0)));
    s.balls.push_back(tennis_ball(1, Vec2(court.surround_length_m / 2.0 - r - 0.10,
                                          -(court.surround_width_m / 2.0 - r - 0.10))));
    s.balls.push_back(tennis_ball(2, Vec2(13.0, -5.0)));
    s.robot.pose = {Vec2(8.0, -5.0), 0.0};
    sim::CourtObstacle person;
    person.pose.position = Vec2(10.5, -5.0);
    s.obstacles = {person};
  };
  const auto system = std::find_if(eval::loop_systems().begin(), eval::loop_systems().end(),
                                   [](const eval::LoopSystem& s) { return s.name == "ballsight"; });
  const TempDir temp;
  RecordOptions mcap;
  mcap.path = temp / "run.mcap";
  mcap.frame_every = 10;
  mcap.wait_for_room = true;
  const eval::LoopRun run = eval::run_loop(
      *system, scene, 200.0,
      [](CourtService& service, NavigationHub& hub) {
        return std::make_unique<LoopbackRobotLink>(service, hub);
      },
      temp / "truth.jsonl", {}, &mcap);
  EXPECT_EQ(run.collected, 3);
  EXPECT_EQ(run.reachable, 3);
  EXPECT_FALSE(run.timed_out);
  EXPECT_LT(run.time_s, 60.0);
  EXPECT_EQ(run.obstacles, "person") << "the scene's own person";

  // The body's distance to the person alone (a court with no net and a far fence), every tick.
  const LoopTruth truth = read_loop_truth(temp / "truth.jsonl");
  sim::TennisCourtSpec open;
  open.net.enabled = false;
  open.surround_length_m = open.surround_width_m = 1000.0;
  sim::CourtObstacle person;
  person.pose.position = Vec2(10.5, -5.0);
  double nearest = INFINITY;
  for (const TruthTick& t : truth.ticks) {
    nearest = std::min(nearest, sim::footprint_clearance(sim::RobotFootprint::of({}, 0.30, 0.70),
                                                         t.world.robot, open, {&person, 1}));
  }
  EXPECT_GT(nearest, 0.2) << "the robot went round the person";
  EXPECT_LT(nearest, 1.5) << "and past it";

  // Every update the service published is in the file, the robot's reports with them.
  const nlohmann::json info = mcap::mcap_info(mcap::McapReader::open(temp / "run.mcap"));
  EXPECT_TRUE(info["complete"].get<bool>());
  std::map<std::string, std::uint64_t> messages;
  for (const auto& c : info["channels"]) messages[c["topic"]] = c["messages"];
  EXPECT_GE(messages["/navigation"], truth.ticks.back().seq) << info.dump(1);
  EXPECT_GT(messages["/robot/reports"], 2u) << "the collected balls and the basket";
  // The frames of every 10th frame set.
  EXPECT_GT(messages["/camera/camera_0/image"], 0u);
  EXPECT_LT(messages["/camera/camera_0/image"] * 8, messages["/navigation"]);
}

}  // namespace
}  // namespace ballsight::test
