#include "ballsight/pipeline/capture.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

#include "ballsight/core/error.hpp"
#include "ballsight/core/utc_clock.hpp"

namespace ballsight {
namespace {

using namespace std::chrono_literals;

Frame frame_with(std::uint64_t sequence) {
  return {cv::Mat(2, 2, CV_8UC3), sequence, {}};
}

TEST(BoundedFrameQueue, DropsTheOldestFramesWhenFull) {
  BoundedFrameQueue queue(2);
  for (std::uint64_t i = 0; i < 5; ++i) queue.push_dropping_oldest(frame_with(i));
  EXPECT_EQ(queue.size(), 2u);
  EXPECT_EQ(queue.dropped(), 3u);
  EXPECT_EQ(queue.pop(0ms)->sequence, 3u);
  EXPECT_EQ(queue.pop(0ms)->sequence, 4u);
  EXPECT_FALSE(queue.pop(1ms).has_value());
}

TEST(BoundedFrameQueue, NewestDropsTheStaleOnesAndCloseWakesWaiters) {
  BoundedFrameQueue queue(3);
  for (std::uint64_t i = 0; i < 3; ++i) queue.push_dropping_oldest(frame_with(i));
  EXPECT_EQ(queue.pop_newest()->sequence, 2u);
  EXPECT_EQ(queue.dropped(), 2u);
  EXPECT_EQ(queue.size(), 0u);
  queue.push_dropping_oldest(frame_with(7));
  queue.push_dropping_oldest(frame_with(8));
  queue.push_dropping_oldest(frame_with(9));
  std::thread waiter([&] { EXPECT_FALSE(queue.push_waiting(frame_with(10))); });  // full: waits
  std::this_thread::sleep_for(5ms);
  queue.close();
  waiter.join();
}

TEST(CaptureOptions, BackoffDoublesUpToTheCap) {
  CaptureOptions options;
  options.backoff.initial = 10ms;
  options.backoff.max = 50ms;
  EXPECT_EQ(options.backoff.after(1), 10ms);
  EXPECT_EQ(options.backoff.after(2), 20ms);
  EXPECT_EQ(options.backoff.after(3), 40ms);
  EXPECT_EQ(options.backoff.after(4), 50ms);
  options.backoff.factor = 0.5;
  EXPECT_THROW(options.validate(), InputError);
  options.backoff.factor = 2.0;
  options.queue_capacity = 0;
  EXPECT_THROW(options.validate(), InputError);
}

// A live source that cannot be opened `failures` times, then delivers frames (counted).
class FlakySource final : public FrameSource {
 public:
  FlakySource(int failures, std::atomic<int>& opens) : failures_(failures), opens_(opens) {}
  std::string describe() const override { return "flaky"; }
  void open() override {
    if (++opens_ <= failures_) throw std::runtime_error("cannot connect");
  }
  std::optional<cv::Mat> read() override {
    std::this_thread::sleep_for(1ms);
    return cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(static_cast<double>(opens_.load())));
  }
  bool live() const override { return true; }

 private:
  int failures_;
  std::atomic<int>& opens_;
};

CaptureOptions fast_retries() {
  CaptureOptions options;
  options.backoff.initial = 2ms;
  options.backoff.max = 8ms;
  return options;
}

// A source that fails to open is retried with back-off and then captures; each failure is logged.
TEST(CameraCapture, RetriesAFailingSourceWithBackoff) {
  std::atomic<int> opens{0};
  std::atomic<int> messages{0};
  CameraCapture capture("east", std::make_unique<FlakySource>(3, opens), fast_retries(),
                        [&](const std::string& m) {
                          ++messages;
                          EXPECT_NE(m.find("camera east"), std::string::npos) << m;
                        });
  capture.start();
  const std::optional<Frame> frame = capture.frames().pop(2000ms);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(opens.load(), 4);
  const CaptureStatus status = capture.status();
  EXPECT_EQ(status.failures_total, 3);
  EXPECT_EQ(status.failures_in_a_row, 0);
  EXPECT_EQ(status.last_error, "cannot connect");
  capture.stop();
  EXPECT_GE(messages.load(), 4);  // three failures and the recovery
}

// One camera that never connects does not hold up the others: frame sets go on without it.
TEST(CameraCapture, OtherCamerasContinueWhileOneIsDown) {
  std::atomic<int> opens_good{0}, opens_bad{0};
  CameraCapture good("good", std::make_unique<FlakySource>(0, opens_good), fast_retries());
  CameraCapture bad("bad", std::make_unique<FlakySource>(1 << 30, opens_bad), fast_retries());
  good.start();
  bad.start();
  for (int i = 0; i < 3; ++i) {
    const std::optional<FrameSet> set = next_frame_set({&good, &bad}, 50ms);
    ASSERT_TRUE(set.has_value());
    EXPECT_FALSE(set->cameras[0].image.empty());
    EXPECT_TRUE(set->cameras[1].image.empty());
    EXPECT_EQ(set->cameras[1].camera, 1u);
    // Stamped on the UTC clock when the capture thread received it: within the last minute.
    EXPECT_NEAR(static_cast<double>(set->capture_time_ns()), static_cast<double>(utc_now_ns()),
                60e9);
  }
  EXPECT_GE(opens_bad.load(), 2);
  EXPECT_EQ(bad.status().state, CaptureState::retrying);
  good.stop();
  bad.stop();
  EXPECT_EQ(bad.status().state, CaptureState::stopped);
}

// A live camera's queue keeps only the newest frames while nobody reads it.
TEST(CameraCapture, LiveQueueDropsStaleFrames) {
  std::atomic<int> opens{0};
  CameraCapture capture("live", std::make_unique<FlakySource>(0, opens), fast_retries());
  capture.start();
  std::this_thread::sleep_for(40ms);
  EXPECT_LE(capture.frames().size(), 2u);
  EXPECT_GT(capture.frames().dropped(), 0u);
  const std::optional<Frame> newest = capture.frames().pop_newest();
  ASSERT_TRUE(newest.has_value());
  EXPECT_GE(newest->sequence, capture.frames().dropped());
  capture.stop();
}

// A recorded source gives every frame in turn, then frame sets end.
TEST(CameraCapture, RecordedSourcesDeliverEveryFrameThenEnd) {
  const std::filesystem::path missing = "/nonexistent/frame.png";
  CameraCapture recorded("recorded", make_image_files_source({}, "no files"), fast_retries());
  recorded.start();
  EXPECT_FALSE(next_frame_set({&recorded}, 500ms).has_value());
  EXPECT_EQ(recorded.status().state, CaptureState::finished);
  // A file that cannot be read is retried (it may appear), not skipped.
  std::atomic<int> messages{0};
  CameraCapture broken("broken", make_image_files_source({missing}, "file"), fast_retries(),
                       [&](const std::string&) { ++messages; });
  broken.start();
  std::this_thread::sleep_for(30ms);
  EXPECT_EQ(broken.status().state, CaptureState::retrying);
  EXPECT_GE(messages.load(), 2);
  broken.stop();
}

}  // namespace
}  // namespace ballsight
