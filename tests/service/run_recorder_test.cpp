// The recorder on a running simulated court: every update and frame set in the file, readable
// and checked; every Nth frame set; files split by size; a path that cannot be written.

#include "ballsight/service/run_recorder.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <optional>

#include "ballsight/core/base64.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/record/mcap_info.hpp"
#include "ballsight/service/navigation_json.hpp"
#include "file_size_limit.hpp"
#include "service/recorded_court.hpp"
#include "temp_dir.hpp"
#include "wait_until.hpp"

namespace ballsight {
namespace {

/// Per topic, the messages of a recording in file order.
std::map<std::string, std::vector<nlohmann::json>> messages_by_topic(
    const std::filesystem::path& path) {
  std::map<std::string, std::vector<nlohmann::json>> topics;
  mcap::McapReader::open(path).read([&](const mcap::Channel& channel, const mcap::Message& m) {
    topics[channel.topic].push_back(nlohmann::json::parse(m.data.bytes));
  });
  return topics;
}

TEST(RunRecorder, EveryUpdateAndFrameSetIsInTheFile) {
  const test::TempDir dir;
  RecordOptions options;
  options.path = dir / "run.mcap";
  const RecorderCounts counts = test::record_run(options, 6);
  ASSERT_EQ(counts.dropped, 0u);
  EXPECT_EQ(counts.frame_sets, counts.updates);
  EXPECT_EQ(counts.files, 1u);
  EXPECT_EQ(counts.bytes, std::filesystem::file_size(options.path));

  const nlohmann::json info = mcap::mcap_info(mcap::McapReader::open(options.path));
  EXPECT_EQ(info["summary"], "agrees");
  EXPECT_TRUE(info["complete"].get<bool>());
  auto topics = messages_by_topic(options.path);
  const std::vector<nlohmann::json>& navigation = topics["/navigation"];
  ASSERT_EQ(navigation.size(), counts.updates);
  for (std::size_t i = 0; i < navigation.size(); ++i) {
    EXPECT_EQ(navigation[i]["seq"], i + 1);  // every update, in order
  }
  EXPECT_EQ(topics["/balls"].size(), counts.updates);
  EXPECT_EQ(topics["/route"].size(), counts.updates);
  EXPECT_EQ(topics["/court"].size(), 1u);
  // The health once a second of publish time (the run lasts less than a few seconds), and the
  // clients' reports when they change: none were made, so once.
  ASSERT_GE(topics["/health"].size(), 1u);
  EXPECT_LE(topics["/health"].size(), 1 + counts.updates / 10);
  EXPECT_TRUE(topics["/health"][0].contains("frame_sets")) << topics["/health"][0];
  ASSERT_EQ(topics["/robot/reports"].size(), 1u);
  EXPECT_EQ(topics["/robot/reports"][0]["collected"].size(), 0u);
  // Camera 0's frames decode to the camera's image, with its detections beside them.
  const std::vector<nlohmann::json>& images = topics["/camera/camera_0/image"];
  ASSERT_EQ(images.size(), counts.frame_sets);
  EXPECT_EQ(topics["/camera/camera_0/detections"].size(), counts.frame_sets);
  EXPECT_EQ(images[0]["format"], "jpeg");
  const std::string jpeg = base64_decode(images.back()["data"].get<std::string>(), "image");
  const cv::Mat frame =
      cv::imdecode(std::vector<std::uint8_t>(jpeg.begin(), jpeg.end()), cv::IMREAD_COLOR);
  EXPECT_GT(frame.cols, 600);
  EXPECT_GT(frame.rows, 300);
  // The navigation update's capture time is the frames' time.
  EXPECT_EQ(images.back()["timestamp"]["sec"].get<std::int64_t>(),
            navigation.back()["capture_time_ns"].get<std::int64_t>() / 1'000'000'000);
}

TEST(RunRecorder, EveryNthFrameSetAndFilesSplitBySize) {
  const test::TempDir dir;
  RecordOptions options;
  options.path = dir / "run.mcap";
  options.frame_every = 3;
  options.max_mb = 0.3;
  options.compression = mcap::Compression::lz4;
  const RecorderCounts counts = test::record_run(options, 12);
  ASSERT_EQ(counts.dropped, 0u);
  EXPECT_EQ(counts.frame_sets, (counts.updates + 2) / 3);
  ASSERT_GT(counts.files, 1u);
  std::size_t navigation = 0, images = 0;
  std::uint64_t bytes = 0;
  for (std::uint64_t n = 1; n <= counts.files; ++n) {
    const auto path = n == 1 ? options.path : dir / ("run-" + std::to_string(n) + ".mcap");
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    bytes += std::filesystem::file_size(path);
    const nlohmann::json info = mcap::mcap_info(mcap::McapReader::open(path));
    EXPECT_EQ(info["summary"], "agrees") << path;
    auto topics = messages_by_topic(path);
    EXPECT_EQ(topics["/court"].size(), 1u) << "each file draws the court: " << path;
    navigation += topics["/navigation"].size();
    images += topics["/camera/camera_1/image"].size();
  }
  EXPECT_EQ(navigation, counts.updates);
  EXPECT_EQ(images, counts.frame_sets);
  EXPECT_EQ(bytes, counts.bytes);
}

// A robot's report (a ball collected, its basket) goes into the file with the next update.
TEST(RunRecorder, ClientReportsAreRecordedWhenTheyChange) {
  const test::TempDir dir;
  RecordOptions options;
  options.path = dir / "run.mcap";
  options.queue = 10'000;
  options.frame_every = 0;
  std::optional<RunRecorder> recorder;
  test::RunningService running(test::small_court(),
                               [&](SimulatedCourtService& service, NavigationHub& hub) {
                                 recorder.emplace(hub, service, options);
                               });
  ASSERT_TRUE(test::wait_until([&] { return running.hub.latest_seq() >= 3; }));
  running.hub.add_collected({Vec2(1.25, -2.5)});
  running.hub.set_basket(3);
  const std::uint64_t reported_at = running.hub.latest_seq();
  ASSERT_TRUE(test::wait_until([&] { return running.hub.latest_seq() >= reported_at + 3; }));
  {
    const test::Deadline deadline("stopping the service and finishing the recording");
    running.stop_and_join();
    recorder->finish();
  }
  const std::vector<nlohmann::json> reports = messages_by_topic(options.path)["/robot/reports"];
  ASSERT_GE(reports.size(), 2u);
  EXPECT_TRUE(reports.front()["basket"].is_null());
  EXPECT_EQ(reports.back()["basket"]["held"], 3);
  // (The collected ball is forgotten once frames captured after the report are fused, before
  // the next update: its JSON is checked on a value.)
  ClientReports value;
  value.collected = {Vec2(1.25, -2.5)};
  value.unreachable = {{Vec2(0.5, 1.0), "behind the net post"}};
  const nlohmann::json j = client_reports_json(value);
  EXPECT_EQ(j["collected"], nlohmann::json::parse("[[1.25, -2.5]]"));
  EXPECT_EQ(j["unreachable"][0]["reason"], "behind the net post");
  EXPECT_TRUE(j["robot"].is_null());
}

// The disk fills up mid-run: the recording stops with the error, the file reads as cut short,
// and the service goes on publishing.
TEST(RunRecorder, AFullDiskStopsTheRecordingNotTheService) {
  const test::TempDir dir;
  RecordOptions options;
  options.path = dir / "run.mcap";
  options.queue = 10'000;
  // Room for the file's beginning (the simulated court's empty-court views are 5 MB of it) and a
  // few updates.
  std::optional<test::FileSizeLimit> full_disk(std::in_place, 8'000'000);
  std::optional<RunRecorder> recorder;
  test::RunningService running(test::small_court(),
                               [&](SimulatedCourtService& service, NavigationHub& hub) {
                                 recorder.emplace(hub, service, options);
                               });
  const bool failed = test::wait_until([&] { return !recorder->counts().error.empty(); });
  const std::uint64_t seq_at_failure = running.hub.latest_seq();
  const bool goes_on =
      test::wait_until([&] { return running.hub.latest_seq() >= seq_at_failure + 3; });
  {
    const test::Deadline deadline("stopping the service and finishing the recording");
    running.stop_and_join();
    recorder->finish();
  }
  full_disk.reset();
  ASSERT_TRUE(failed) << "the recording never failed";
  EXPECT_TRUE(goes_on) << "the service stopped at update " << running.hub.latest_seq();
  const RecorderCounts counts = recorder->counts();
  EXPECT_NE(counts.error.find(options.path.string() + ": cannot write"), std::string::npos)
      << counts.error;
  EXPECT_LE(std::filesystem::file_size(options.path), 8'000'000u);
  std::size_t navigation = 0;
  const mcap::DataSection data = mcap::McapReader::open(options.path)
                                     .read([&](const mcap::Channel& channel, const mcap::Message&) {
                                       navigation += channel.topic == "/navigation";
                                     });
  EXPECT_FALSE(data.complete);
  EXPECT_GT(navigation, 0u);
  EXPECT_LE(navigation, counts.updates);
}

TEST(RunRecorder, APathThatCannotBeWrittenIsAnInputError) {
  NavigationHub hub;
  SimulatedCourtService service(test::small_court());
  RecordOptions options;
  options.path = "/nonexistent-dir/run.mcap";
  EXPECT_THROW(RunRecorder(hub, service, options), InputError);
  options.path = "run.mcap";
  options.jpeg_quality = 0;
  EXPECT_THROW(RunRecorder(hub, service, options), InputError);
}

}  // namespace
}  // namespace ballsight
