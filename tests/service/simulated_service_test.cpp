#include "ballsight/service/simulated_service.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "service/running_service.hpp"
#include "temp_dir.hpp"
#include "wait_until.hpp"

namespace ballsight {
namespace {

// A camera fails and returns while nobody drives (the court keeps to the wall clock): the record
// says both, the health says which camera is dark, and the pipeline goes on without it.
TEST(SimulatedService, ACameraFailsAndReturns) {
  const test::TempDir dir;
  SimulatedServiceOptions options;
  options.seed = 3;
  options.balls = 4;
  options.vision_hz = 20.0;
  options.truth_out = dir / "truth.jsonl";
  options.camera_outages = {{2, 0.1, 0.3}, {0, 0.4}};
  test::RunningService running(options);
  const SimulatedCourtService& service = running.service;
  const auto sim_time = [&] { return running.sim_time(); };
  const auto state = [&](int k) { return service.health()["cameras"][k]["state"]; };
  bool saw_failed = false;
  ASSERT_TRUE(test::wait_until([&] {
    if (sim_time() > 0.12 && sim_time() < 0.28) saw_failed = saw_failed || state(2) == "failed";
    return sim_time() >= 0.3;
  })) << "the simulated clock stood at "
      << sim_time() << " s";
  ASSERT_TRUE(test::wait_until([&] { return sim_time() >= 0.5; }))
      << "the simulated clock stood at " << sim_time() << " s";
  EXPECT_EQ(state(2), "simulated");
  EXPECT_EQ(state(0), "failed");
  running.stop_and_join();
  EXPECT_TRUE(saw_failed);

  const LoopTruth truth = read_loop_truth(options.truth_out);
  std::vector<std::string> camera_events;
  for (const TruthEvent& e : truth.events) {
    if (e.what.find("frames") != std::string::npos) camera_events.push_back(e.what);
  }
  const std::vector<std::string> names = {service.site().cameras[2].name,
                                          service.site().cameras[0].name};
  EXPECT_EQ(camera_events, (std::vector<std::string>{names[0] + " failed: no more frames",
                                                     names[0] + " returned: frames again",
                                                     names[1] + " failed: no more frames"}));
  EXPECT_GT(service.health()["frame_sets"].get<int>(), 8);
}

// In lockstep the court waits for the robot's acknowledgement of every update, however long it
// takes (eval loop: a run never depends on the machine's load), and takes the robot's command.
TEST(SimulatedService, InLockstepTheCourtWaitsForEveryAcknowledgement) {
  SimulatedServiceOptions options;
  options.seed = 2;
  options.balls = 3;
  options.lockstep = true;
  test::RunningService running(options);
  SimulatedCourtService& service = running.service;
  const auto sim_time = [&] { return running.sim_time(); };
  const auto published = [&] { return service.health()["frame_sets"].get<std::uint64_t>(); };
  const Pose2D start = service.robot_start();
  for (std::uint64_t seq = 1; seq <= 3; ++seq) {
    ASSERT_TRUE(test::wait_until([&] { return published() >= seq; }))
        << "update " << seq << " was never published";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a slow robot
    EXPECT_EQ(published(), seq);
    EXPECT_DOUBLE_EQ(sim_time(), 0.1 * static_cast<double>(seq - 1));
    service.drive(seq, 0.5, 0.0);
    running.hub.acknowledge(seq);
  }
  ASSERT_TRUE(test::wait_until([&] { return published() >= 4; })) << "update 4 was never published";
  running.stop_and_join();
  EXPECT_NEAR(sim_time(), 0.3, 1e-9);
  const std::vector<sim::WorldTick> ticks = service.history();
  ASSERT_EQ(ticks.size(), 3u);
  EXPECT_GT((ticks.back().robot.position - start.position).norm(), 0.02);  // it drove
}

TEST(SimulatedService, AnOutageMustEndAfterItBegins) {
  SimulatedServiceOptions options;
  options.camera_outages = {{1, 2.0, 1.0}};
  EXPECT_THROW(options.validate(), InputError);
  options.camera_outages = {{4, 1.0}};
  EXPECT_THROW(options.validate(), InputError);
  options.camera_outages = {{3, 1.0, 2.0}, {3, 5.0}};
  EXPECT_NO_THROW(options.validate());
}

}  // namespace
}  // namespace ballsight
