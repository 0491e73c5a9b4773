#include "ballsight/pipeline/planning_input.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

void expect_error(const std::function<void()>& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no error, expected " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(PlanningInput, TheSiteGivesTheCourtTheNetAndTheCollector) {
  Site site;
  site.robot.collector_x_m = 0.4;
  const PlanningProblem p = site_planning_problem(site, {Vec2(-5, 2), kPi / 2}, {Vec2(1, 1)});
  ASSERT_TRUE(p.court && p.court->net);
  EXPECT_NEAR(p.court->net->half_length_m, 10.97 / 2 + 0.914, 1e-12);
  EXPECT_EQ(p.court->area_max_m, Vec2(18.0, 9.0));
  EXPECT_NEAR((p.robot.position - Vec2(-5, 2.4)).norm(), 0.0, 1e-12);
  site.court.net = false;
  EXPECT_FALSE(drivable_court(site.court).net);
  expect_error([&] { site_planning_problem(Site{}, {Vec2(0.02, 1), 0.0}, {}); }, "inside the net");
  // Beyond a post, within the room the route keeps round it: planned from the nearest point out.
  const PlanningProblem round =
      site_planning_problem(Site{}, {Vec2(-0.02, 6.6), rad_from_deg(-90.0)}, {Vec2(5, 5)});
  EXPECT_FALSE(round.court->in_net_zone(round.robot.position));
  EXPECT_NEAR(round.robot.position.x(), -Site{}.court.net_clearance_m, 1e-12);  // out sideways
  EXPECT_NEAR(round.robot.position.y(), 6.3, 1e-12);
}

TEST(PlanningInput, WorldJsonAndCsv) {
  const WorldBalls w = parse_world_balls(
      R"({"balls": [{"x_m": 1.5, "y_m": -2}], "robot": {"x_m": 3, "y_m": 4, "heading_deg": 90}})",
      "w.json");
  ASSERT_EQ(w.balls.size(), 1u);
  EXPECT_EQ(w.balls[0], Vec2(1.5, -2));
  ASSERT_TRUE(w.robot);
  EXPECT_NEAR(w.robot->heading_rad, kPi / 2, 1e-12);
  EXPECT_EQ(parse_ball_csv("x_m,y_m\r\n1,2\r\n\n 3 , 4\n", "b.csv"),
            (std::vector<Vec2>{Vec2(1, 2), Vec2(3, 4)}));
  expect_error([] { parse_world_balls("{", "w.json"); }, "w.json: not valid JSON");
  expect_error([] { parse_world_balls(R"({"balls": 3})", "w.json"); }, "'balls' (a list)");
  expect_error([] { parse_world_balls(R"({"balls": [{"x_m": "a", "y_m": 1}]})", "w.json"); },
               "w.json: balls[0].x_m: expected a finite number");
  expect_error([] { parse_ball_csv("", "b.csv"); }, "b.csv: empty");
  expect_error([] { parse_ball_csv("x_m,y_m\n1,2,3\n", "b.csv"); }, "b.csv:2: expected two");
  expect_error([] { parse_ball_csv("x_m,y_m\n1,inf\n", "b.csv"); }, "b.csv:2:3: y_m");
}

}  // namespace
}  // namespace ballsight
