#include "ballsight/eval/lut_plot.hpp"

#include <gtest/gtest.h>

#include "ballsight/calib/lut_inspect.hpp"
#include "calib/iris_ramp_table.hpp"

namespace ballsight {
namespace {

TEST(LutInspect, PlotHasTheFigureSizeAndColour) {
  const InspectedLut lut = inspected_from_iris(test::ramp_table(200), "plot");
  const cv::Mat figure = plot_lut_inspection(lut, inspect_lut(lut));
  EXPECT_EQ(figure.type(), CV_8UC3);
  EXPECT_GT(figure.cols, 1000);
  cv::Mat channels[3];
  cv::split(figure, channels);
  EXPECT_GT(cv::norm(channels[0], channels[2], cv::NORM_L1), 1e5);  // a coloured heat map
}

}  // namespace
}  // namespace ballsight
