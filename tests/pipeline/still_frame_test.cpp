#include "ballsight/pipeline/still_frame.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "ballsight/core/error.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using namespace std::chrono_literals;

StillFrameOptions quick_retries(int attempts, int live_frames = 1) {
  StillFrameOptions options;
  options.attempts = attempts;
  options.backoff = {1ms, 4ms, 2.0};
  options.live_frames = live_frames;
  return options;
}

std::string error_of(FrameSource& source, const StillFrameOptions& options) {
  try {
    read_still_frame(source, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A live source that cannot be opened `failures` times, then gives frames of grey level 7.
class FlakySource final : public FrameSource {
 public:
  explicit FlakySource(int failures) : failures_(failures) {}
  std::string describe() const override { return "flaky camera"; }
  void open() override {
    if (++opens_ <= failures_) throw std::runtime_error("cannot connect to flaky camera");
  }
  std::optional<cv::Mat> read() override { return cv::Mat(4, 6, CV_8UC3, cv::Scalar::all(7)); }
  bool live() const override { return true; }
  int opens() const { return opens_; }

 private:
  int failures_;
  int opens_ = 0;
};

// A video file read as a URL source (cv::VideoCapture opens files and streams alike): the first
// frame, or the mean of the first few. FFV1 (lossless) so the grey levels are exact.
TEST(StillFrame, LiveFramesAreAveraged) {
  const test::TempDir dir;
  const std::string video = (dir / "greys.avi").string();
  {
    cv::VideoWriter writer(video, cv::VideoWriter::fourcc('F', 'F', 'V', '1'), 5, {64, 48});
    ASSERT_TRUE(writer.isOpened()) << "OpenCV cannot write FFV1 .avi here";
    for (double grey : {10.0, 20.0, 60.0, 110.0}) {
      writer.write(cv::Mat(48, 64, CV_8UC3, cv::Scalar::all(grey)));
    }
  }
  const auto grey_of = [&](int live_frames) {
    const std::unique_ptr<FrameSource> source = make_url_source(video);
    const cv::Mat still = read_still_frame(*source, quick_retries(1, live_frames));
    EXPECT_EQ(still.size(), cv::Size(64, 48));
    EXPECT_EQ(still.type(), CV_8UC3);
    return cv::mean(still)[0];
  };
  EXPECT_DOUBLE_EQ(grey_of(1), 10.0);
  EXPECT_DOUBLE_EQ(grey_of(3), 30.0);
  EXPECT_DOUBLE_EQ(grey_of(10), 50.0);  // the video ends after four frames: their mean
}

TEST(StillFrame, ALiveSourceIsRetriedWithBackoff) {
  FlakySource flaky(2);
  const cv::Mat still = read_still_frame(flaky, quick_retries(3));
  EXPECT_EQ(flaky.opens(), 3);
  EXPECT_EQ(cv::mean(still)[0], 7.0);

  FlakySource dead(5);
  EXPECT_EQ(error_of(dead, quick_retries(2)),
            "cannot connect to flaky camera (gave up after 2 attempts)");
  EXPECT_EQ(dead.opens(), 2);
}

TEST(StillFrame, AVideoDeviceThatDoesNotExistIsAClearError) {
  const std::unique_ptr<FrameSource> device = make_device_source(97);
  EXPECT_EQ(error_of(*device, quick_retries(2)),
            "cannot open video device 97 (gave up after 2 attempts)");
}

// Recorded sources: the first image by name, read once (no retry: a missing file stays missing).
TEST(StillFrame, RecordedSourcesGiveTheirFirstImage) {
  const test::TempDir dir;
  const std::unique_ptr<FrameSource> empty = make_image_folder_source(dir.path());
  EXPECT_EQ(error_of(*empty, quick_retries(3)), "no image in folder " + dir.path().string());
  cv::imwrite((dir / "b.png").string(), cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(2)));
  cv::imwrite((dir / "a.png").string(), cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(1)));
  const std::unique_ptr<FrameSource> folder = make_image_folder_source(dir.path());
  EXPECT_EQ(cv::mean(read_still_frame(*folder, quick_retries(3, 5)))[0], 1.0);
  const std::unique_ptr<FrameSource> missing =
      make_image_files_source({dir / "none.png"}, "file none.png");
  EXPECT_EQ(error_of(*missing, quick_retries(3)),
            (dir / "none.png").string() + ": cannot open for reading");
}

TEST(StillFrame, OptionsAreChecked) {
  FlakySource source(0);
  EXPECT_THROW(read_still_frame(source, quick_retries(0)), InputError);
  EXPECT_THROW(read_still_frame(source, quick_retries(1, 0)), InputError);
}

}  // namespace
}  // namespace ballsight
