#include <gtest/gtest.h>

#include "ballsight/core/utc_clock.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight {
namespace {

// A report stands for one ball, the nearest: in a cluster it does not hide the balls beside the
// one the robot took (the collector standing still before a cluster's last two balls, session 32).
TEST(TakenByReports, OneBallPerReportTheNearestFirst) {
  const std::vector<Vec2> cluster{Vec2(10.65, -2.33), Vec2(10.63, -2.39), Vec2(10.71, -2.37)};
  EXPECT_EQ(taken_by_reports(cluster, {Vec2(10.65, -2.32)}),
            (std::vector<bool>{true, false, false}));
  // Two reports near the same two balls: each takes the one nearest to it, not both the first.
  EXPECT_EQ(taken_by_reports(cluster, {Vec2(10.72, -2.37), Vec2(10.66, -2.35)}),
            (std::vector<bool>{true, false, true}));
  // Nothing within the match distance: no ball is taken; no report: none.
  EXPECT_EQ(taken_by_reports(cluster, {Vec2(12.0, -2.3)}), (std::vector<bool>(3, false)));
  EXPECT_EQ(taken_by_reports(cluster, {}), (std::vector<bool>(3, false)));
  EXPECT_TRUE(taken_by_reports({}, {Vec2(1.0, 1.0)}).empty());
  // More reports than balls: each ball once.
  EXPECT_EQ(taken_by_reports({Vec2(0.0, 0.0)}, {Vec2(0.05, 0.0), Vec2(0.0, 0.05)}),
            std::vector<bool>{true});
}

// A report lasts until frames captured after it are fused: those show the ball gone, and a ball
// they still show there is planned again.
TEST(NavigationHub, ForgetsCollectedReportsOnceLaterFramesAreFused) {
  NavigationHub hub;
  const std::int64_t before = utc_now_ns();
  hub.add_collected({Vec2(3.0, 4.0), Vec2(1.0, 1.0)});
  hub.frames_fused(before);  // frames captured before the report: it stays
  EXPECT_EQ(hub.collected(), (std::vector<Vec2>{Vec2(3.0, 4.0), Vec2(1.0, 1.0)}));
  EXPECT_EQ(hub.reports().collected, hub.collected());
  hub.frames_fused(utc_now_ns() + 1);
  EXPECT_TRUE(hub.collected().empty());
  EXPECT_TRUE(hub.reports().collected.empty());
}

// A court nobody drives takes each reported ball off by hand once, whenever the report came.
TEST(NavigationHub, HandsEachReportOutOnce) {
  NavigationHub hub;
  hub.add_collected({Vec2(3.0, 4.0)});
  EXPECT_EQ(hub.take_for_hand(), std::vector<Vec2>{Vec2(3.0, 4.0)});
  EXPECT_TRUE(hub.take_for_hand().empty());
  hub.frames_fused(utc_now_ns() + 1);  // the planner forgets it; the hand had it already
  hub.add_collected({Vec2(1.0, 2.0)});
  hub.frames_fused(utc_now_ns() + 1);  // forgotten by the planner before the hand came by
  EXPECT_EQ(hub.take_for_hand(), std::vector<Vec2>{Vec2(1.0, 2.0)});
  EXPECT_EQ(hub.collected(), std::vector<Vec2>{});
}

}  // namespace
}  // namespace ballsight
