// What differs from the empty court (detect/court_foreground.hpp): one blob per changed region, its
// pixels as the patch; noise and specks are not blobs; a frame of another size is refused.
#include "ballsight/detect/court_foreground.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

cv::Mat noisy(const cv::Mat& image, int seed) {
  cv::Mat noise(image.size(), CV_16SC3);
  cv::theRNG().state = static_cast<std::uint64_t>(seed);
  cv::randn(noise, 0, 2);
  cv::Mat out;
  cv::add(image, noise, out, cv::noArray(), CV_8UC3);
  return out;
}

TEST(CourtForeground, ABlobWhereSomethingStandsAndNoneElse) {
  const cv::Mat court(360, 640, CV_8UC3, cv::Scalar(88, 128, 70));
  CourtForeground foreground(noisy(court, 1));
  EXPECT_TRUE(foreground.detect(noisy(court, 2)).empty());

  cv::Mat frame = court.clone();
  cv::rectangle(frame, cv::Rect(300, 100, 20, 60), cv::Scalar(40, 40, 150), cv::FILLED);
  cv::rectangle(frame, cv::Rect(50, 50, 3, 3), cv::Scalar(40, 40, 150), cv::FILLED);  // a speck
  const std::vector<PixelDetection> found = foreground.detect(noisy(frame, 3));
  ASSERT_EQ(found.size(), 1u);
  const PixelDetection& d = found[0];
  EXPECT_EQ(d.object, ObjectClass::obstacle);
  EXPECT_NEAR(d.area_px, 1200.0, 100.0);
  EXPECT_NEAR(d.center_px.x(), 310.0, 1.0);
  EXPECT_NEAR(d.center_px.y(), 130.0, 1.0);
  EXPECT_EQ(d.patch.x, 300);
  EXPECT_EQ(d.patch.height, 60);
  EXPECT_EQ(d.patch.at(310, 159), 1.0f);
  EXPECT_EQ(d.patch.at(300, 100), 1.0f);

  EXPECT_THROW(foreground.detect(cv::Mat(100, 100, CV_8UC3)), InputError);
  EXPECT_THROW(CourtForeground(cv::Mat(10, 10, CV_8UC1)), InputError);
  EXPECT_THROW(CourtForeground(court, ForegroundOptions{0, 80.0}), InputError);
}

}  // namespace
}  // namespace ballsight
