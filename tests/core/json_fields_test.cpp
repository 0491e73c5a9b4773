// Poses in JSON: written and read back; a reading that is not a pose is skipped, not refused.
#include "ballsight/core/json_fields.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TEST(JsonPose, ReadsBackWhatWasWritten) {
  const Pose2D pose{Vec2(1.5, -2.25), rad_from_deg(30.0)};
  const Pose2D back = json_pose(pose_json(pose), "pose");
  EXPECT_DOUBLE_EQ(back.position.x(), 1.5);
  EXPECT_DOUBLE_EQ(back.position.y(), -2.25);
  EXPECT_NEAR(back.heading_rad, rad_from_deg(30.0), 1e-12);
  EXPECT_THROW(json_pose(nlohmann::json{{"x_m", 1.0}}, "pose"), InputError);
}

TEST(JsonPose, IfAnyIsNoneForAMissingOrBadMember) {
  const nlohmann::json reply{{"odometry", pose_json({Vec2(0.5, 0.25), 0.0})},
                             {"bad", {{"x_m", "one"}, {"y_m", 0.0}, {"heading_deg", 0.0}}}};
  const std::optional<Pose2D> odometry = json_pose_if_any(reply, "odometry");
  ASSERT_TRUE(odometry);
  EXPECT_DOUBLE_EQ(odometry->position.x(), 0.5);
  EXPECT_FALSE(json_pose_if_any(reply, "missing"));
  EXPECT_FALSE(json_pose_if_any(reply, "bad"));
  EXPECT_FALSE(json_pose_if_any(nlohmann::json(3), "odometry"));
}

}  // namespace
}  // namespace ballsight
