#pragma once
// A navigation update as ROS 2 messages in the court frame (x, y on the court, z up, metres):
// the robot's pose, the balls (a PoseArray, and ballsight's BallArray with covariance and
// cameras), the route (nav_msgs/Path, one pose per waypoint, each facing the next) and the
// service's health (diagnostic_msgs/DiagnosticArray). Strings and sequences live in `arena`.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/dds/message_arena.hpp"
#include "ballsight/dds/message_types.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight::dds {

/// The frame_id of every court message.
inline constexpr const char* kCourtFrame = "court";

HeaderMsg header_message(std::int64_t stamp_ns, const std::string& frame_id, MessageArena& arena);
/// UTC nanoseconds of a header's stamp.
std::int64_t stamp_ns(const HeaderMsg& header);
/// The same of a serialized message (Reader::take_serialized) whose first member is a
/// std_msgs/Header (every stamped message here); throws InputError for bytes too short or not
/// plain CDR.
std::int64_t serialized_stamp_ns(const std::vector<std::uint8_t>& cdr);

/// A pose on the court: z 0, turned `heading_rad` about z.
PoseMsg pose_message(const Pose2D& pose);
Pose2D pose_from_message(const PoseMsg& pose);

/// The robot as the cameras saw it (nullopt when they did not), stamped with the capture time.
std::optional<PoseStampedMsg> robot_pose_message(const NavigationUpdate& update,
                                                 MessageArena& arena);
/// The balls' centres (z = `ball_radius_m`), facing +x.
PoseArrayMsg balls_message(const NavigationUpdate& update, double ball_radius_m,
                           MessageArena& arena);
BallArrayMsg ball_estimates_message(const NavigationUpdate& update, double ball_radius_m,
                                    MessageArena& arena);
PathMsg route_message(const NavigationUpdate& update, MessageArena& arena);

/// A court service's health (CourtService::health()) as diagnostics: one status per camera
/// ("<prefix>/camera/<name>": OK while it runs, WARN while it retries or starts, ERROR when it
/// stopped) and one for the pipeline ("<prefix>/pipeline": WARN with its last error).
DiagnosticArrayMsg diagnostics_message(const nlohmann::json& health, const std::string& prefix,
                                       std::int64_t stamp_ns, MessageArena& arena);

}  // namespace ballsight::dds
