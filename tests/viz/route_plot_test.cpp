#include "ballsight/viz/route_plot.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

TEST(RoutePlot, APointProblemFillsAbout1200PixelsWhateverItsUnits) {
  for (const double unit : {1.0, 1000.0}) {
    PlanningProblem problem;
    problem.robot.position = Vec2(0, 0);
    problem.balls = {unit * Vec2(10, 2), unit * Vec2(-5, 8), unit * Vec2(3, -4)};
    const cv::Mat image = draw_route_map(problem, CourtFloor{}, {}, "points");
    EXPECT_NEAR(image.cols, 1200, 2) << "unit " << unit;
  }
}

TEST(RoutePlot, TheNetIsDrawnOnlyWhereThePlannedCourtHasOne) {
  CourtFloor floor;
  floor.surround = {Vec2(-18, -9), Vec2(18, 9)};
  floor.court = floor.surround;
  floor.court_bgr = floor.surround_bgr = {90, 120, 70};
  floor.net_posts_y_m = 6.4;
  floor.net_bgr = {0, 0, 250};
  PlanningProblem problem;
  problem.robot.position = Vec2(-10, -5);
  problem.court = DrivableCourt::standard();
  // The view: the fence and a metre round it at 32 px/m below a 36 px title.
  const cv::Point net(static_cast<int>((0 + 19) * 32.0), 36 + static_cast<int>((10 - 5.0) * 32.0));
  const cv::Mat with_net = draw_route_map(problem, floor, {}, "net");
  EXPECT_EQ(with_net.at<cv::Vec3b>(net), cv::Vec3b(0, 0, 250));
  problem.court->net.reset();
  const cv::Mat without = draw_route_map(problem, floor, {}, "no net");
  EXPECT_EQ(without.at<cv::Vec3b>(net), cv::Vec3b(90, 120, 70));
}

}  // namespace
}  // namespace ballsight
