#include "ballsight/viz/chart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace ballsight {
namespace {

// A tick step is 1, 2 or 5 times a power of ten.
bool round_step(double step) {
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  return std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
         std::abs(mantissa - 5.0) < 1e-9;
}

TEST(Chart, TicksAreRoundEvenlySpacedAndInsideTheRange) {
  const std::pair<double, double> ranges[] = {
      {0.0, 1.0}, {-3.7, 12.2}, {599.5, 600.5}, {0.0, 2304.0}, {-0.013, 0.004}};
  for (const auto& [lo, hi] : ranges) {
    const std::vector<double> ticks = nice_ticks(lo, hi, 6);
    ASSERT_GE(ticks.size(), 3u) << lo << ".." << hi;
    EXPECT_LE(ticks.size(), 12u) << lo << ".." << hi;
    const double step = ticks[1] - ticks[0];
    EXPECT_TRUE(round_step(step)) << "step " << step << " for " << lo << ".." << hi;
    for (std::size_t i = 0; i < ticks.size(); ++i) {
      EXPECT_GE(ticks[i], lo - 1e-9 * step);
      EXPECT_LE(ticks[i], hi + 1e-9 * step);
      if (i > 0) {
        EXPECT_NEAR(ticks[i] - ticks[i - 1], step, 1e-9 * step);
      }
    }
  }
  EXPECT_TRUE(nice_ticks(1.0, 1.0).empty());
  EXPECT_TRUE(nice_ticks(2.0, 1.0).empty());
}

TEST(Chart, NiceCeilIsTheNextRoundValueAtOrAbove) {
  EXPECT_DOUBLE_EQ(nice_ceil(1.0), 1.0);
  EXPECT_DOUBLE_EQ(nice_ceil(7.3), 8.0);
  EXPECT_DOUBLE_EQ(nice_ceil(433.0), 500.0);
  EXPECT_DOUBLE_EQ(nice_ceil(0.0), 1.0);  // an empty plot still has an axis
  for (const double v : {0.37, 3.3, 41.0, 999.0, 1234.5}) EXPECT_GE(nice_ceil(v), v);
}

TEST(Chart, AxesMapTheDataRangeOntoTheAreaWithYUp) {
  const ChartAxes axes{cv::Rect(100, 50, 400, 200), -1.0, 3.0, 10.0, 20.0};
  const cv::Point2d bottom_left = axes.to_image(-1.0, 10.0);
  const cv::Point2d top_right = axes.to_image(3.0, 20.0);
  EXPECT_DOUBLE_EQ(bottom_left.x, 100.0);
  EXPECT_DOUBLE_EQ(bottom_left.y, 250.0);
  EXPECT_DOUBLE_EQ(top_right.x, 500.0);
  EXPECT_DOUBLE_EQ(top_right.y, 50.0);
  const cv::Point2d middle = axes.to_image(1.0, 15.0);
  EXPECT_DOUBLE_EQ(middle.x, 300.0);
  EXPECT_DOUBLE_EQ(middle.y, 150.0);
}

TEST(Chart, ColorizePaintsInvalidValuesInTheirOwnColour) {
  cv::Mat1f values(1, 3);
  values << 0.0f, std::nanf(""), 10.0f;
  const cv::Mat bgr = colorize(values, cv::COLORMAP_TURBO, 0.0, 10.0, cv::Scalar(1, 2, 3));
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(1, 2, 3));
  EXPECT_NE(bgr.at<cv::Vec3b>(0, 0), bgr.at<cv::Vec3b>(0, 2));  // the two ends of the map
}

}  // namespace
}  // namespace ballsight
