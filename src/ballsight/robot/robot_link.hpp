#pragma once
// The robot's side of the navigation service, whatever carries it (docs/robot-link.md): a link
// that delivers every navigation update in order, takes the robot's acknowledgements, reports of
// collected balls and pose, and, on the simulated court, the robot's wheel command. Over HTTP and
// WebSocket: net/http_robot_link.hpp.

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/plan/obstacle_detours.hpp"

namespace ballsight {

/// One navigation update as the robot needs it.
struct LinkUpdate {
  std::uint64_t seq = 0;
  std::string service_id;
  std::int64_t capture_time_ns = 0;
  std::int64_t published_ns = 0;
  std::int64_t received_ns = 0;  // UTC, when this client had it
  std::optional<Pose2D> robot;   // the robot as the cameras saw it
  std::vector<Vec2> balls_m;
  std::vector<Vec2> visits_m;     // where the collector passes, in order
  std::vector<Vec2> waypoints_m;  // the path to drive
  /// Where the route empties the basket before its next ball (none: it does not).
  std::optional<Vec2> unload_first_m;
  std::vector<ObstacleDisc> obstacles;  // what stands on the court, as the cameras saw it
};

struct LinkStatus {
  bool connected = false;
  std::string transport;  // "websocket", "long-poll" or "dds"
  std::uint64_t delivered = 0;
  std::uint64_t gaps = 0;  // updates the service published that this client never got
  int reconnects = 0;
  std::string last_error;
};

/// Thread-safe; an implementation receives on a thread of its own.
class RobotLink {
 public:
  virtual ~RobotLink() = default;

  /// The next update not taken yet, oldest first, waiting up to `timeout`.
  virtual std::optional<LinkUpdate> next(std::chrono::milliseconds timeout) = 0;
  /// The newest update, dropping older ones not taken, waiting up to `timeout`.
  virtual std::optional<LinkUpdate> latest(std::chrono::milliseconds timeout) = 0;

  /// These return false (and set last_error) when the service could not be reached or refused.
  virtual bool acknowledge(std::uint64_t seq) = 0;
  /// Balls collected at `positions`, and the balls the basket holds now when `held` says (0
  /// after emptying it, with no positions).
  virtual bool report_collected(const std::vector<Vec2>& positions, std::optional<int> held) = 0;
  /// Balls it gave up on (it could not reach them), and why: the service plans without them.
  virtual bool report_unreachable(const std::vector<Vec2>& positions,
                                  const std::string& reason) = 0;
  virtual bool set_pose(const Pose2D& pose) = 0;
  /// The simulated court only: the wheels' command for update `seq` (speed m/s, turn rate deg/s,
  /// counter-clockwise); answers {"collected", "held", "time_s", "odometry"}, nullopt when
  /// refused.
  virtual std::optional<nlohmann::json> drive_simulated(std::uint64_t seq, double speed_mps,
                                                        double turn_rate_dps) = 0;

  virtual LinkStatus status() const = 0;
  virtual void stop() = 0;
};

}  // namespace ballsight
