#include "ballsight/eval/plot_inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/calib/lut_inspect.hpp"
#include "calib/iris_ramp_table.hpp"

namespace ballsight {
namespace {

TEST(LutInspect, PlotHasTheFigureSizeAndColour) {
  const InspectedLut lut = inspected_from_iris(test::ramp_table(200), "plot");
  const cv::Mat figure = plot_lut_figure(lut_figure_input(lut, inspect_lut(lut)));
  EXPECT_EQ(figure.type(), CV_8UC3);
  EXPECT_GT(figure.cols, 1000);
  cv::Mat channels[3];
  cv::split(figure, channels);
  EXPECT_GT(cv::norm(channels[0], channels[2], cv::NORM_L1), 1e5);  // a coloured heat map
}

TEST(PlotInputs, ALutProfileIsTheRayOverItsWrittenRangeOnly) {
  const InspectedLut lut = inspected_from_iris(test::ramp_table(200), "ramp");
  const LutFigureInput figure = lut_figure_input(lut, inspect_lut(lut));
  EXPECT_EQ(figure.title, "ramp  (iris-px2cm)");
  ASSERT_EQ(figure.radius_px.size(), static_cast<std::size_t>(lut.rays.bins));
  for (std::size_t k = 0; k < kLutFigureDirectionsDeg.size(); ++k) {
    ASSERT_TRUE(figure.profiles[k]) << "theta " << kLutFigureDirectionsDeg[k];
    const LutProfile& profile = *figure.profiles[k];
    EXPECT_FALSE(profile.drop_px);  // the ramp rises everywhere
    const std::span<const float> ray = lut.rays.ray(kLutFigureDirectionsDeg[k]);
    for (std::size_t i = 0; i < figure.radius_px.size(); i += 50) {
      if (figure.radius_px[i] < 19.9) {
        EXPECT_TRUE(std::isnan(profile.distance_cm[i])) << "unwritten at " << figure.radius_px[i];
      } else if (std::isfinite(ray[i])) {
        EXPECT_EQ(profile.distance_cm[i], ray[i]);
      }
    }
  }
  EXPECT_GT(figure.largest_distance_cm, 0.0);
  EXPECT_TRUE(figure.monotonic_label.starts_with("monotonic over the written range"));
}

TEST(PlotInputs, TheCourtFloorIsTheSimulatorsCourt) {
  sim::TennisCourtSpec court;
  const CourtFloor floor = court_floor(court);
  EXPECT_EQ(floor.court.max_m, Vec2(court.length_m / 2, court.doubles_width_m / 2));
  EXPECT_EQ(floor.surround.min_m, Vec2(-court.surround_length_m / 2, -court.surround_width_m / 2));
  EXPECT_EQ(floor.lines.size(), court.line_rects().size());
  EXPECT_EQ(floor.court_bgr,
            cv::Scalar(court.court_bgr[0], court.court_bgr[1], court.court_bgr[2]));
  ASSERT_TRUE(floor.net_posts_y_m);
  EXPECT_DOUBLE_EQ(*floor.net_posts_y_m,
                   court.doubles_width_m / 2 + court.net.post_outside_doubles_m);
  court.net.enabled = false;
  EXPECT_FALSE(court_floor(court).net_posts_y_m);
}

TEST(PlotInputs, ALoopRecordGivesThePathTheRoutesAndWhenEachBallWasCollected) {
  LoopTruth truth;
  truth.balls = {{1, Vec2(1, 1)}, {2, Vec2(2, 2)}};
  truth.robot_start.position = Vec2(-5, 0);
  for (int i = 1; i <= 3; ++i) {
    TruthTick& tick = truth.ticks.emplace_back();
    tick.world.time_s = 0.5 * i;
    tick.world.robot.position = Vec2(-5 + i, 0);
    if (i >= 2) tick.world.collected = {1};  // reported again on later ticks
    if (i != 2) tick.published.waypoints_m = {Vec2(-5 + i, 0), Vec2(1, 1)};
  }
  const LoopMapInput run = loop_map_input(truth);
  EXPECT_EQ(run.path_m.size(), 3u);
  ASSERT_EQ(run.routes.size(), 2u);  // the tick without a route left out
  EXPECT_DOUBLE_EQ(run.routes[1].time_s, 1.5);
  ASSERT_EQ(run.balls.size(), 2u);
  ASSERT_TRUE(run.balls[0].collected_s);
  EXPECT_DOUBLE_EQ(*run.balls[0].collected_s, 1.0);  // the first report
  EXPECT_FALSE(run.balls[1].collected_s);
  EXPECT_DOUBLE_EQ(run.duration_s, 1.5);
}

TEST(PlotInputs, MistakesAreMarkedWithTheirKindsInitial) {
  const std::vector<MistakeMark> marks =
      mistake_marks({{BallMistake::Kind::missed, Vec2(1, 2), 0},
                     {BallMistake::Kind::duplicate, Vec2(3, 4), 0},
                     {BallMistake::Kind::false_positive, Vec2(5, 6), 1}});
  ASSERT_EQ(marks.size(), 3u);
  EXPECT_EQ(marks[0].letter, 'M');
  EXPECT_EQ(marks[1].letter, 'D');
  EXPECT_EQ(marks[2].letter, 'F');
  EXPECT_EQ(marks[2].position_m, Vec2(5, 6));
}

TEST(PlotInputs, OnlyCalibratedMethodsAreEstimateLayersInTheOptionsDistances) {
  OmniExperimentResult result;
  result.options.distances_cm = {200, 120};
  result.methods["poly"].by_distance[120].estimates_cm = {Vec2(1, 1)};
  result.methods["poly"].by_distance[200].estimates_cm = {Vec2(2, 2), std::nullopt};
  result.methods["ballsight-auto"];  // could not be calibrated
  const std::vector<EstimateLayer> layers = estimate_layers(result);
  ASSERT_EQ(layers.size(), 1u);
  EXPECT_EQ(layers[0].label, "poly");
  ASSERT_EQ(layers[0].estimates_cm.size(), 2u);
  EXPECT_EQ(layers[0].estimates_cm[0].size(), 2u);  // 200 cm first, as the options list it
}

}  // namespace
}  // namespace ballsight
