#include "ballsight/dds/court_messages.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight::dds {
namespace {

constexpr std::int64_t kNsPerS = 1'000'000'000;

// Every scalar member of `object` as a key/value pair (arrays and objects left out).
void fill_values(const nlohmann::json& object, DiagnosticStatusMsg& status, MessageArena& arena) {
  std::size_t n = 0;
  for (const auto& [key, value] : object.items()) n += value.is_primitive() ? 1 : 0;
  KeyValueMsg* values = arena.fill(status.values, n);
  for (const auto& [key, value] : object.items()) {
    if (!value.is_primitive()) continue;
    values->key = arena.text(key);
    values->value = arena.text(value.is_string() ? value.get<std::string>() : value.dump());
    ++values;
  }
}

std::uint8_t camera_level(const std::string& state) {
  if (state == "running" || state == "simulated") return 0;  // OK
  if (state == "stopped" || state == "finished") return 2;   // ERROR
  return 1;                                                  // WARN: starting, retrying
}

}  // namespace

HeaderMsg header_message(std::int64_t stamp_ns, const std::string& frame_id, MessageArena& arena) {
  HeaderMsg header{};
  const std::int64_t sec = stamp_ns >= 0 ? stamp_ns / kNsPerS : -((-stamp_ns - 1) / kNsPerS) - 1;
  header.stamp.sec = static_cast<std::int32_t>(sec);
  header.stamp.nanosec = static_cast<std::uint32_t>(stamp_ns - sec * kNsPerS);
  header.frame_id = arena.text(frame_id);
  return header;
}

std::int64_t stamp_ns(const HeaderMsg& header) {
  return header.stamp.sec * kNsPerS + header.stamp.nanosec;
}

std::int64_t serialized_stamp_ns(const std::vector<std::uint8_t>& cdr) {
  // Encapsulation (00 00: big-endian CDR, 00 01: little-endian), then int32 sec, uint32 nanosec.
  require(cdr.size() >= 12 && cdr[0] == 0 && cdr[1] <= 1, "serialized message",
          "expected plain CDR of at least 12 bytes beginning with a header");
  const auto word = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t byte = cdr[1] == 1 ? at + 3 - k : at + k;  // most significant first
      v = (v << 8) | cdr[byte];
    }
    return v;
  };
  return static_cast<std::int32_t>(word(4)) * kNsPerS + word(8);
}

PoseMsg pose_message(const Pose2D& pose) {
  PoseMsg message{};
  message.position.x = pose.position.x();
  message.position.y = pose.position.y();
  message.orientation.z = std::sin(pose.heading_rad / 2.0);
  message.orientation.w = std::cos(pose.heading_rad / 2.0);
  return message;
}

Pose2D pose_from_message(const PoseMsg& pose) {
  const auto& q = pose.orientation;  // yaw of a rotation about any axis, as tf2 reads it
  return {{pose.position.x, pose.position.y},
          std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))};
}

std::optional<PoseStampedMsg> robot_pose_message(const NavigationUpdate& update,
                                                 MessageArena& arena) {
  if (!update.world.robot) return std::nullopt;
  PoseStampedMsg message{};
  message.header = header_message(update.capture_time_ns, kCourtFrame, arena);
  message.pose = pose_message(update.world.robot->pose);
  return message;
}

PoseArrayMsg balls_message(const NavigationUpdate& update, double ball_radius_m,
                           MessageArena& arena) {
  PoseArrayMsg message{};
  message.header = header_message(update.capture_time_ns, kCourtFrame, arena);
  PoseMsg* poses = arena.fill(message.poses, update.world.balls.size());
  for (const FusedBall& ball : update.world.balls) {
    *poses = pose_message({ball.position_m, 0.0});
    (poses++)->position.z = ball_radius_m;
  }
  return message;
}

BallArrayMsg ball_estimates_message(const NavigationUpdate& update, double ball_radius_m,
                                    MessageArena& arena) {
  BallArrayMsg message{};
  message.header = header_message(update.capture_time_ns, kCourtFrame, arena);
  message.seq = update.seq;
  BallMsg* balls = arena.fill(message.balls, update.world.balls.size());
  for (const FusedBall& ball : update.world.balls) {
    BallMsg& b = *balls++;
    b.position.x = ball.position_m.x();
    b.position.y = ball.position_m.y();
    b.position.z = ball_radius_m;
    for (int k = 0; k < 4; ++k) b.covariance[k] = ball.covariance_m2(k / 2, k % 2);
    std::int32_t* cameras = arena.fill(b.cameras, ball.cameras.size());
    for (const int c : ball.cameras) *cameras++ = c;
  }
  return message;
}

PathMsg route_message(const NavigationUpdate& update, MessageArena& arena) {
  PathMsg message{};
  message.header = header_message(update.capture_time_ns, kCourtFrame, arena);
  const std::vector<Vec2>& waypoints = update.route.waypoints_m;
  PoseStampedMsg* poses = arena.fill(message.poses, waypoints.size());
  double heading_rad = update.world.robot ? update.world.robot->pose.heading_rad : 0.0;
  for (std::size_t k = 0; k < waypoints.size(); ++k) {
    if (k + 1 < waypoints.size() && waypoints[k + 1] != waypoints[k]) {
      const Vec2 d = waypoints[k + 1] - waypoints[k];
      heading_rad = std::atan2(d.y(), d.x());
    }  // the last waypoint keeps the heading it is reached with
    poses[k].header = message.header;
    poses[k].pose = pose_message({waypoints[k], heading_rad});
  }
  return message;
}

DiagnosticArrayMsg diagnostics_message(const nlohmann::json& health, const std::string& prefix,
                                       std::int64_t stamp_ns, MessageArena& arena) {
  DiagnosticArrayMsg message{};
  message.header = header_message(stamp_ns, "", arena);
  const nlohmann::json cameras = health.value("cameras", nlohmann::json::array());
  DiagnosticStatusMsg* status = arena.fill(message.status, cameras.size() + 1);
  for (const nlohmann::json& camera : cameras) {
    const std::string name = camera.value("name", "");
    const std::string state = camera.value("state", "");
    status->level = camera_level(state);
    status->name = arena.text(prefix + "/camera/" + name);
    status->message = arena.text(state);
    status->hardware_id = arena.text(name);
    fill_values(camera, *status++, arena);
  }
  const std::string error = health.value("last_error", "");
  status->level = error.empty() ? 0 : 1;
  status->name = arena.text(prefix + "/pipeline");
  status->message = arena.text(error.empty() ? "ok" : error);
  status->hardware_id = arena.text("");
  fill_values(health, *status, arena);
  return message;
}

}  // namespace ballsight::dds
