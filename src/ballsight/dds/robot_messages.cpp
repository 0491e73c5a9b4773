#include "ballsight/dds/robot_messages.hpp"

#include <algorithm>

#include "ballsight/core/utc_clock.hpp"
#include "ballsight/dds/court_messages.hpp"

namespace ballsight::dds {

NavigationUpdateMsg navigation_update_message(const NavigationUpdate& update,
                                              const std::string& service_id, double ball_radius_m,
                                              MessageArena& arena) {
  NavigationUpdateMsg message{};
  message.header = header_message(update.capture_time_ns, kCourtFrame, arena);
  message.seq = update.seq;
  message.service_id = arena.text(service_id);
  message.published = header_message(update.published_ns, "", arena).stamp;
  if (update.world.robot) {
    message.has_robot = true;
    message.robot = pose_2d_message(update.world.robot->pose);
  }
  std::vector<Vec2> balls(update.world.balls.size());
  std::transform(update.world.balls.begin(), update.world.balls.end(), balls.begin(),
                 [](const FusedBall& b) { return b.position_m; });
  fill_points(message.balls, balls, arena, ball_radius_m);
  fill_points(message.visits, update.route.visits_m, arena);
  fill_points(message.waypoints, update.route.waypoints_m, arena);
  if (update.route.unloads_first() && update.route.unload_m) {
    message.unload_first = true;
    message.unload = {update.route.unload_m->x(), update.route.unload_m->y(), 0.0};
  }
  return message;
}

LinkUpdate link_update_from_message(const NavigationUpdateMsg& message) {
  LinkUpdate out;
  out.seq = message.seq;
  out.service_id = message.service_id ? message.service_id : "";
  out.capture_time_ns = stamp_ns(message.header);
  HeaderMsg published{};
  published.stamp = message.published;
  out.published_ns = stamp_ns(published);
  if (message.has_robot) out.robot = pose_from_message(message.robot);
  out.balls_m = points_from_message(message.balls);
  out.visits_m = points_from_message(message.visits);
  out.waypoints_m = points_from_message(message.waypoints);
  if (message.unload_first) out.unload_first_m = Vec2(message.unload.x, message.unload.y);
  return out;
}

RobotReportMsg report_message(ReportKind kind, const std::string& client, std::uint64_t request,
                              MessageArena& arena) {
  RobotReportMsg message{};
  message.header = header_message(utc_now_ns(), kCourtFrame, arena);
  message.client = arena.text(client);
  message.request = request;
  message.kind = static_cast<std::uint8_t>(kind);
  message.held = -1;
  message.reason = arena.text("");
  return message;
}

Pose2DMsg pose_2d_message(const Pose2D& pose) {
  return {pose.position.x(), pose.position.y(), pose.heading_rad};
}

Pose2D pose_from_message(const Pose2DMsg& pose) {
  return {{pose.x, pose.y}, pose.theta};
}

RobotReplyMsg reply_message(const RobotReportMsg& report, const std::string& error,
                            MessageArena& arena) {
  RobotReplyMsg message{};
  message.header = header_message(utc_now_ns(), kCourtFrame, arena);
  message.client = arena.text(report.client ? report.client : "");
  message.request = report.request;
  message.ok = error.empty();
  message.error = arena.text(error);
  return message;
}

}  // namespace ballsight::dds
