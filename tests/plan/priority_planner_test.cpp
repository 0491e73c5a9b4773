// The report's priority rule (section 7.11) against its printed test results (Figures 8.2, 8.4):
// positions in cm as printed, the robot's heading from its back to its front marker.
#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/plan/greedy_planners.hpp"
#include "ballsight/plan/planner.hpp"

namespace ballsight {
namespace {

struct PrintedBall {
  Vec2 position_cm;
  double priority;
};

Pose2D pose_from_markers_cm(const Vec2& back_cm, const Vec2& front_cm) {
  const Vec2 d = front_cm - back_cm;
  return {front_cm / 100.0, std::atan2(d.y(), d.x())};
}

void expect_printed(const Pose2D& robot, const std::vector<PrintedBall>& balls) {
  for (const PrintedBall& b : balls) {
    SCOPED_TRACE(testing::Message() << "ball at " << b.position_cm.transpose());
    EXPECT_NEAR(report_priority(robot, b.position_cm / 100.0, PriorityWeights{}), b.priority, 0.01);
  }
}

TEST(PriorityPlanner, Figure82PrioritiesComeOutWithTheDerivedWeights) {
  // "Blue as back of robot x = 12.6196 y = 40.07 Pink as front of robot x = 28.8469 y = 53.8442"
  const Pose2D robot = pose_from_markers_cm({12.6196, 40.07}, {28.8469, 53.8442});
  const std::vector<PrintedBall> printed{{{97.115, 113.847}, 32.4532},
                                         {{-0.499519, 92.2189}, 73.5109},
                                         {{13.7095, 194.551}, 85.8113},
                                         {{93.2487, 235.516}, 87.0631}};
  expect_printed(robot, printed);
  // The planner takes the ball the report ranked first (its "Index 2", our ball 0), not the
  // nearest (its "Index 1", our ball 1).
  PlanningProblem problem;
  problem.robot = robot;
  for (const PrintedBall& b : printed) problem.balls.push_back(b.position_cm / 100.0);
  PlannerOptions options;
  options.kind = PlannerKind::priority;
  const Route route = plan(problem, options);
  ASSERT_EQ(route.order.size(), 4u);
  EXPECT_EQ(route.order[0], 0);
}

TEST(PriorityPlanner, Figure84PrintedRowsFollowTheSameWeights) {
  // Figure 8.4's marker coordinates are garbled in the scan (its distances do not follow from
  // them), but its printed distance, angle and priority rows fit the same weights.
  const PriorityWeights w;
  EXPECT_NEAR(w.priority(124.072, 47.1713), 74.0867, 0.001);
  EXPECT_NEAR(w.priority(117.116, 90.5943), 99.8769, 0.001);
  EXPECT_NEAR(w.priority(98.5082, 147.062), 130.068, 0.001);
}

}  // namespace
}  // namespace ballsight
