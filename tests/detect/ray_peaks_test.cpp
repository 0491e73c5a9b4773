#include "ballsight/detect/ray_peaks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

// Vertical white bars on a grey floor, crossed by the ray from (10, 50) along +x (image angle 0).
struct Bar {
  double left, width;
};

cv::Mat1b bars_image(const std::vector<Bar>& bars) {
  cv::Mat1b image(100, 300, uchar{60});
  for (const Bar& b : bars) {
    for (int x = 0; x < image.cols; ++x) {
      // The pixel's share of the bar: pixel x covers [x - 0.5, x + 0.5).
      const double covered =
          std::clamp(std::min(x + 0.5, b.left + b.width) - std::max(x - 0.5, b.left), 0.0, 1.0);
      if (covered > 0.0) image.col(x).setTo(cv::saturate_cast<uchar>(60 + covered * 150));
    }
  }
  return image;
}

std::vector<RayPeak> peaks_of(const std::vector<Bar>& bars) {
  return ray_peaks(bars_image(bars), {10.0, 50.0}, 0.0, 5.0, 280.0, RayPeakOptions{});
}

TEST(RayPeaks, ALineIsFoundAtItsCentreWhateverItsWidth) {
  const std::vector<Bar> bars{{40.2, 1.5}, {80.0, 4.0}, {120.5, 12.0}, {170.0, 30.0}};
  const std::vector<RayPeak> peaks = peaks_of(bars);
  ASSERT_EQ(peaks.size(), bars.size());
  for (std::size_t i = 0; i < bars.size(); ++i) {
    // The ray starts at x = 10: a bar's centre lies at radius left + width / 2 - 10.
    EXPECT_NEAR(peaks[i].radius_px, bars[i].left + 0.5 * bars[i].width - 10.0, 0.15) << i;
    // Above both sides by most of the bar's 150 grey levels (a thin bar's pixels are partly
    // floor; a wide one is tried at widths a third apart).
    EXPECT_GT(peaks[i].height, 85.0) << i;
    EXPECT_NEAR(peaks[i].width_px, bars[i].width, 0.35 * bars[i].width + 1.0) << i;
  }
}

TEST(RayPeaks, TwoThinLinesCloseTogetherAreTwo) {
  const std::vector<RayPeak> peaks = peaks_of({{100.0, 2.0}, {106.0, 2.0}});
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_NEAR(peaks[0].radius_px, 91.0, 0.15);
  EXPECT_NEAR(peaks[1].radius_px, 97.0, 0.15);
}

TEST(RayPeaks, AStepIsNoLine) {
  cv::Mat1b image(100, 300, uchar{60});
  image.colRange(150, 300).setTo(200);  // a bright floor from x = 150 on
  EXPECT_TRUE(ray_peaks(image, {10.0, 50.0}, 0.0, 5.0, 280.0, RayPeakOptions{}).empty());
}

TEST(RayPeaks, ABadWidthIsNamed) {
  try {
    RayPeakOptions{.min_contrast = 25.0, .max_width_px = 0.5}.validate();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("max_width_px"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ballsight
