#include "ballsight/service/loop_truth.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

TruthTick sample_tick(double time_s, std::vector<int> collected, int left) {
  TruthTick t;
  t.world.time_s = time_s;
  t.world.robot = {Vec2(1.0, 2.0 + time_s), 0.5};
  t.world.collected = std::move(collected);
  t.world.balls_left = left;
  t.seq = static_cast<std::uint64_t>(time_s * 10);
  t.command = {0.8, -0.2};
  t.published.robot = Pose2D{Vec2(1.01, 2.0), 0.49};
  t.published.balls_seen = left;
  t.published.waypoints_m = {Vec2(1, 2), Vec2(3, 4)};
  return t;
}

void write_lines(const std::filesystem::path& file, const std::vector<nlohmann::json>& lines,
                 const std::string& tail = "") {
  std::ofstream out(file);
  for (const nlohmann::json& j : lines) out << j.dump() << "\n";
  out << tail;
}

TEST(LoopTruth, RecordsReadBackAndScore) {
  const test::TempDir dir;
  const auto file = dir / "truth.jsonl";
  const Pose2D start{Vec2(1.0, 2.0), 0.5};
  write_lines(file, {scene_record(7, {{0, Vec2(1, 3)}, {1, Vec2(1, 4)}}, start),
                     event_record({0.0, "service started"}), tick_record(sample_tick(1.0, {0}, 1)),
                     tick_record(sample_tick(2.0, {1}, 0))});
  const LoopTruth truth = read_loop_truth(file);
  EXPECT_EQ(truth.seed, 7u);
  ASSERT_EQ(truth.balls.size(), 2u);
  EXPECT_EQ(truth.balls[1].position_m, Vec2(1, 4));
  ASSERT_EQ(truth.ticks.size(), 2u);
  EXPECT_EQ(truth.ticks[0].world.collected, std::vector<int>{0});
  EXPECT_EQ(truth.ticks[1].seq, 20u);
  EXPECT_NEAR(truth.ticks[1].command.turn_rate_rps, -0.2, 1e-12);
  ASSERT_TRUE(truth.ticks[1].published.robot);
  EXPECT_EQ(truth.ticks[1].published.waypoints_m.back(), Vec2(3, 4));
  ASSERT_EQ(truth.events.size(), 1u);
  EXPECT_EQ(truth.events[0].what, "service started");

  std::vector<sim::WorldTick> ticks;
  for (const TruthTick& t : truth.ticks) ticks.push_back(t.world);
  const LoopScore score = score_loop(2, start, ticks, sim::RobotFootprint{});
  EXPECT_TRUE(score.all);
  EXPECT_EQ(score.collected, 2);
  EXPECT_DOUBLE_EQ(score.time_s, 2.0);
  EXPECT_NEAR(score.distance_m, 2.0, 1e-12);  // (1, 2) -> (1, 3) -> (1, 4)
  EXPECT_TRUE(score.never_overlapped);
}

TEST(LoopTruth, ALineCutByAKillIsDroppedAndBadLinesAreNamed) {
  const test::TempDir dir;
  const auto file = dir / "truth.jsonl";
  const nlohmann::json scene = scene_record(1, {}, Pose2D{});
  write_lines(file, {scene, tick_record(sample_tick(1.0, {}, 0))}, "{\"kind\": \"ti");
  EXPECT_EQ(read_loop_truth(file).ticks.size(), 1u);
  drop_unfinished_line(file);
  EXPECT_EQ(read_file(file).back(), '\n');
  EXPECT_EQ(read_loop_truth(file).ticks.size(), 1u);

  nlohmann::json bad = tick_record(sample_tick(1.0, {}, 0));
  bad.erase("balls_left");
  write_lines(file, {scene, bad, tick_record(sample_tick(2.0, {}, 0))});
  try {
    read_loop_truth(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("truth.jsonl:2:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("balls_left"), std::string::npos) << e.what();
  }
  write_lines(file, {tick_record(sample_tick(1.0, {}, 0))});
  EXPECT_THROW(read_loop_truth(file), InputError);  // no scene first
  EXPECT_THROW(read_loop_truth(dir / "missing.jsonl"), InputError);
}

}  // namespace
}  // namespace ballsight
