#pragma once
// The robot link's messages (docs/ros2.md): a navigation update as the robot reads it, the
// robot's reports to its court and the court's replies. Strings and sequences live in `arena`.

#include <cstdint>
#include <string>
#include <vector>

#include "ballsight/dds/message_arena.hpp"
#include "ballsight/dds/message_types.hpp"
#include "ballsight/dds/topic_io.hpp"
#include "ballsight/robot/robot_link.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight::dds {

/// The topics of the robot link, under the participant's namespace, and their QoS (all
/// reliable, keep last 64, so that updates written back to back all arrive): the updates
/// transient-local, a robot that joins getting the latest one at once; reports and replies
/// volatile.
inline constexpr const char* kNavigationTopic = "navigation";
inline constexpr const char* kReportsTopic = "robot/reports";
inline constexpr const char* kRepliesTopic = "robot/replies";
inline constexpr TopicQos kNavigationQos{true, 64, 1};
inline constexpr TopicQos kReportQos{false, 64};
/// Points one report may carry at most (API v1's body limit allows about 2500).
inline constexpr std::size_t kMaxReportPoints = 1024;

/// What a RobotReport asks (its `kind`).
enum class ReportKind : std::uint8_t {
  acknowledge = 0,
  collected = 1,
  pose = 2,
  drive = 3,
  unreachable = 4
};

/// `update` of the service `service_id`, the balls' centres at z = `ball_radius_m`.
NavigationUpdateMsg navigation_update_message(const NavigationUpdate& update,
                                              const std::string& service_id, double ball_radius_m,
                                              MessageArena& arena);
/// The robot's view of a navigation update (received_ns left 0).
LinkUpdate link_update_from_message(const NavigationUpdateMsg& message);

/// A report of `kind` from `client`'s request `request`, stamped now; the caller fills in what
/// the kind carries (fill_points, pose_2d_message, seq, speeds).
RobotReportMsg report_message(ReportKind kind, const std::string& client, std::uint64_t request,
                              MessageArena& arena);
/// Points on the court (z 0) into a sequence of geometry_msgs/Point, and back.
template <class Sequence>
void fill_points(Sequence& sequence, const std::vector<Vec2>& points, MessageArena& arena,
                 double z = 0.0) {
  auto* out = arena.fill(sequence, points.size());
  for (const Vec2& p : points) *out++ = {p.x(), p.y(), z};
}
template <class Sequence>
std::vector<Vec2> points_from_message(const Sequence& sequence) {
  std::vector<Vec2> out;
  out.reserve(sequence._length);
  for (std::uint32_t k = 0; k < sequence._length; ++k)
    out.emplace_back(sequence._buffer[k].x, sequence._buffer[k].y);
  return out;
}
Pose2DMsg pose_2d_message(const Pose2D& pose);
Pose2D pose_from_message(const Pose2DMsg& pose);

/// The reply to `report`, stamped now: ok when `error` is empty.
RobotReplyMsg reply_message(const RobotReportMsg& report, const std::string& error,
                            MessageArena& arena);

}  // namespace ballsight::dds
