#include "ballsight/viz/lut_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ballsight {
namespace {

// A 200 x 100 px table whose rays rise with the radius from 10 px, one direction dropping at
// 30 px.
LutFigureInput rising_table() {
  LutFigureInput lut;
  lut.title = "test table";
  lut.summary = "first written 10.0 px";
  for (int bin = 0; bin < 500; ++bin) lut.radius_px.push_back(bin / 10.0);
  lut.radius_end_px = 50.0;
  for (auto& profile : lut.profiles) {
    profile.emplace();
    for (const double r : lut.radius_px) profile->distance_cm.push_back(r < 10.0 ? NAN : 4.0 * r);
  }
  lut.profiles[2]->drop_px = 30.0;
  lut.profiles[2]->distance_at_drop_cm = 120.0;
  lut.largest_distance_cm = 196.0;
  lut.monotonic_until_px = 30.0;
  lut.monotonic_label = "monotonic until 30.0 px (theta 90)";
  lut.distance_image_cm = cv::Mat1f(100, 200, 80.0f);
  lut.distance_image_cm(0, 0) = NAN;
  lut.image_center_px = Vec2(99.5, 49.5);
  return lut;
}

TEST(LutPlot, TheFigureHasItsSizeAColouredHeatMapAndGreyHoles) {
  const cv::Mat figure = plot_lut_figure(rising_table());
  ASSERT_EQ(figure.type(), CV_8UC3);
  EXPECT_EQ(figure.size(), cv::Size(1500, 730));
  // The heat map fills (930, 130, 440, 220): a value of 80 of 200 cm is coloured, not grey.
  const cv::Vec3b inside = figure.at<cv::Vec3b>(240, 1100);
  EXPECT_FALSE(inside[0] == inside[1] && inside[1] == inside[2]);
  EXPECT_EQ(figure.at<cv::Vec3b>(131, 931), cv::Vec3b(235, 235, 235));  // the missing value
}

TEST(LutPlot, DirectionsNeverWrittenAreLeftOut) {
  LutFigureInput lut = rising_table();
  const cv::Mat all = plot_lut_figure(lut);
  for (auto& profile : lut.profiles) profile.reset();
  const cv::Mat none = plot_lut_figure(lut);
  // The profiles' panel (x 110..850, y 130..650) loses its curves and legend; the heat map stays.
  EXPECT_GT(
      cv::norm(all(cv::Rect(110, 130, 740, 520)), none(cv::Rect(110, 130, 740, 520)), cv::NORM_L1),
      1e4);
  EXPECT_EQ(
      cv::norm(all(cv::Rect(930, 130, 440, 200)), none(cv::Rect(930, 130, 440, 200)), cv::NORM_L1),
      0.0);
}

}  // namespace
}  // namespace ballsight
