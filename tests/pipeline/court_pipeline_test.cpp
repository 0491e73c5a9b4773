#include "ballsight/pipeline/court_pipeline.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "field_cameras.hpp"

namespace ballsight {
namespace {

std::vector<FieldCamera> two_cameras() {
  const FieldCamera camera = test::overhead_camera({320, 240}, 300.0, 6.0);
  return {camera, camera};
}

// A frame of another size than its camera's calibration is not used, and the result says why;
// the other camera's frame is used. Both methods.
TEST(CourtPipeline, FrameOfTheWrongSizeIsReportedNotUsed) {
  const cv::Mat good(240, 320, CV_8UC3, cv::Scalar(70, 128, 88));
  const cv::Mat wrong(480, 640, CV_8UC3, cv::Scalar(70, 128, 88));
  for (auto& pipeline :
       {make_seed_pipeline(two_cameras()), make_ballsight_pipeline(two_cameras())}) {
    SCOPED_TRACE(court_method_name(pipeline->method()));
    FrameSet frames = frame_set_of({good, wrong}, 1000);
    frames.cameras[1].capture_time_ns = 500;  // older, but not used: not the world's time
    const FrameSetResult result = pipeline->process(frames);
    EXPECT_TRUE(result.camera_errors[0].empty());
    EXPECT_NE(result.camera_errors[1].find("640x480"), std::string::npos)
        << result.camera_errors[1];
    EXPECT_NE(result.camera_errors[1].find("320x240"), std::string::npos)
        << result.camera_errors[1];
    EXPECT_TRUE(result.detections[0].has_value());
    EXPECT_FALSE(result.detections[1].has_value());
    EXPECT_EQ(result.world.cameras, (std::vector<int>{0}));
    EXPECT_EQ(result.world.capture_time_ns, 1000);
    const FrameSetResult missing = pipeline->process(frame_set_of({cv::Mat(), good}, 2000));
    EXPECT_EQ(missing.camera_errors[0], "no frame");
    EXPECT_EQ(missing.world.cameras, (std::vector<int>{1}));
    EXPECT_EQ(missing.world.capture_time_ns, 2000);
  }
}

TEST(CourtPipeline, WrongNumberOfFramesIsAnError) {
  const auto pipeline = make_ballsight_pipeline(two_cameras());
  EXPECT_THROW(pipeline->process(frame_set_of({cv::Mat()}, 0)), InputError);
  FrameSet swapped = frame_set_of({cv::Mat(), cv::Mat()}, 0);
  std::swap(swapped.cameras[0], swapped.cameras[1]);
  EXPECT_THROW(pipeline->process(swapped), InputError);  // not in camera order
}

// The set is as old as its oldest frame.
TEST(FrameSet, CaptureTimeIsTheOldestFrames) {
  FrameSet set = frame_set_of({cv::Mat(2, 2, CV_8UC3), cv::Mat(), cv::Mat(2, 2, CV_8UC3)}, 50);
  EXPECT_TRUE(set.any());
  set.cameras[2].capture_time_ns = 40;
  set.cameras[1].capture_time_ns = 10;  // no image: not counted
  EXPECT_EQ(set.capture_time_ns(), 40);
  EXPECT_EQ(set.capture_time_ns({true, true, false}), 50);  // camera 2's frame not used
  set.cameras[0].capture_time_ns = 0;                       // a frame stamped 0 counts too
  EXPECT_EQ(set.capture_time_ns(), 0);
  EXPECT_FALSE(frame_set_of({cv::Mat()}, 5).any());
  EXPECT_EQ(frame_set_of({cv::Mat()}, 5).capture_time_ns(), 0);
}

}  // namespace
}  // namespace ballsight
