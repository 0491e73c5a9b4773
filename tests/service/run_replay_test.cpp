// A recorded run replayed (service/run_replay.hpp, service/replay_service.hpp): with lossless
// frames and the same build nothing differs, update by update; another planner shows what it
// changes; frames that were not recorded are said to be missing; a file without a setup is
// refused by name; `serve --replay`'s service publishes what the recording holds.

#include "ballsight/service/run_replay.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "ballsight/record/mcap_writer.hpp"
#include "ballsight/service/replay_service.hpp"
#include "service/recorded_court.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

RecordOptions lossless(const std::filesystem::path& path) {
  RecordOptions options;
  options.path = path;
  options.frames = FrameEncoding::png;
  options.queue = 1000;  // PNG is slow: no update is dropped, the writer catches up at the end
  return options;
}

// Reports that change the plans mid-run: a ball collected (re-planned at once, without new
// frames), the basket's count, a ball given up.
void report_mid_run(test::RunningService& running) {
  const std::optional<NavigationUpdate> first = running.hub.latest();
  ASSERT_TRUE(first && first->world.balls.size() >= 3);
  running.hub.add_collected({first->world.balls[0].position_m});
  running.hub.set_basket(1);
  running.service.republish(running.hub);
  running.hub.mark_unreachable({first->world.balls[1].position_m}, "stuck");
  running.service.republish(running.hub);
}

TEST(RunReplay, ALosslessRecordingReplaysWithNoDifference) {
  const test::TempDir dir;
  const RecorderCounts counts =
      test::record_run(lossless(dir / "run.mcap"), 12, test::small_court(), report_mid_run);
  ASSERT_EQ(counts.dropped, 0u);
  const RecordedRun run(dir / "run.mcap");
  EXPECT_EQ(run.frames(), "png");
  EXPECT_EQ(run.cut(), "");
  int replans = 0;
  bool reported = false;
  run.for_each_update([&](const RecordedUpdate& u) {
    replans += !u.new_frame_set;
    reported = reported || (!u.reports.collected.empty() && !u.reports.unreachable.empty());
    return true;
  });
  EXPECT_GE(replans, 2);  // the two re-plans of the reports, without new frames
  EXPECT_TRUE(reported);

  const nlohmann::json r = replay_json(replay_run(run), true);
  EXPECT_EQ(r["updates"], counts.updates);
  EXPECT_EQ(r["replayed"], counts.updates);
  EXPECT_EQ(r["differing"], 0) << r.dump(1);
  // Not merely within tolerance: the same numbers.
  EXPECT_EQ(r["ball_shift_max_m"], 0.0);
  EXPECT_EQ(r["robot_shift_max_m"], 0.0);
  EXPECT_EQ(r["robot_turn_max_deg"], 0.0);
  EXPECT_EQ(r["routes_changed"], 0);
  int robots = 0;
  for (const auto& u : r["per_update"]) robots += u["robot"] == "same";
  EXPECT_GT(robots, 0) << "the robot was seen in the recorded updates";

  // Another planner plans other routes over the same balls.
  ReplayOptions nearest;
  nearest.planner = PlannerKind::nearest;
  const nlohmann::json n = replay_json(replay_run(run, nearest));
  EXPECT_EQ(n["balls_added"], 0);
  EXPECT_EQ(n["balls_lost"], 0);
  EXPECT_GT(n["routes_changed"], 0) << n.dump(1);
}

TEST(RunReplay, FramesNotRecordedAreNotReplayed) {
  const test::TempDir dir;
  RecordOptions options = lossless(dir / "run.mcap");
  options.frame_every = 3;
  const RecorderCounts counts = test::record_run(options, 9);
  const nlohmann::json r = replay_json(replay_run(RecordedRun(dir / "run.mcap")));
  EXPECT_EQ(r["updates"], counts.updates);
  EXPECT_EQ(r["replayed"], counts.frame_sets);
  EXPECT_EQ(r["not_replayed"].get<std::uint64_t>(), counts.updates - counts.frame_sets);
  ASSERT_FALSE(r["per_update"].empty());
  EXPECT_EQ(r["per_update"][0]["not_replayed"], "its frames were not recorded");
}

TEST(RunReplay, AFileWithoutItsSetupIsRefusedByName) {
  const test::TempDir dir;
  mcap::McapWriter(dir / "bare.mcap", {}).close();
  try {
    const RecordedRun run(dir / "bare.mcap");
    FAIL() << "read a file without a setup";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bare.mcap"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("replay/site.yml"), std::string::npos) << e.what();
  }
  EXPECT_THROW(RecordedRun(dir / "missing.mcap"), InputError);
}

// `serve --replay`'s court: every recorded update published again, as fast as it goes, the
// last one the recording's; then it holds the last update until stopped.
TEST(ReplayCourtService, PublishesTheRecordedRun) {
  const test::TempDir dir;
  const RecorderCounts counts = test::record_run(lossless(dir / "run.mcap"), 8);
  ReplayServiceOptions options;
  options.speed = 0.0;
  ReplayCourtService service(dir / "run.mcap", options);
  EXPECT_EQ(service.camera_names().size(), 4u);
  NavigationHub hub;
  std::atomic<bool> stop{false};
  std::thread runner([&] { service.run(hub, stop); });
  const bool finished = test::wait_until([&] { return service.health()["replay"]["finished"]; });
  stop = true;
  runner.join();
  ASSERT_TRUE(finished);
  const nlohmann::json health = service.health();
  EXPECT_EQ(health["replay"]["updates"], counts.updates);
  EXPECT_EQ(health["replay"]["replayed"], counts.updates);
  EXPECT_EQ(health["cameras"][0]["state"], "finished");
  EXPECT_EQ(health["cameras"][0]["frames"], counts.frame_sets);
  EXPECT_EQ(hub.latest_seq(), counts.updates);
  RecordedRun(dir / "run.mcap").for_each_update([&](const RecordedUpdate& u) {
    if (u.seq == counts.updates) {
      EXPECT_EQ(u.capture_time_ns, hub.latest()->capture_time_ns);
    }
    return true;
  });
  ASSERT_TRUE(service.camera_view(0));  // the dashboard's camera views
  EXPECT_THROW(ReplayCourtService(dir / "run.mcap", {-1.0, {}}), InputError);
}

}  // namespace
}  // namespace ballsight
