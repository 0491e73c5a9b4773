#pragma once
// The robot's side of the navigation service over HTTP (docs/robot-link.md): a client that
// receives every
// navigation update over the WebSocket stream (or, where the stream is refused, by long-polling),
// acknowledges them, reports collected balls and may set the robot's pose. When the service goes
// away it reconnects with back-off and resumes after the last sequence number it delivered, so a
// target is neither lost nor given twice; a restarted service (a new service id) is followed from
// its latest update. Thread-safe; the receiving runs on a thread of its own.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/net/link_update.hpp"
#include "ballsight/pipeline/frame_source.hpp"
#include "ballsight/robot/link_inbox.hpp"
#include "ballsight/robot/robot_link.hpp"

namespace ballsight {

struct RobotLinkOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8080;
  std::string token;                            // for acknowledgements, collected balls, pose
  bool websocket = true;                        // false: long-poll only
  std::chrono::milliseconds poll_wait{5000};    // a long-poll's timeout_ms
  std::chrono::milliseconds io_timeout{20000};  // silence after which the link is renewed
  BackoffOptions backoff{std::chrono::milliseconds(100), std::chrono::milliseconds(2000), 2.0};
  std::size_t keep = 256;  // updates delivered but not yet taken, at most (oldest dropped)

  /// "http://HOST:PORT" (or "HOST:PORT"); throws InputError naming `where` otherwise.
  static RobotLinkOptions from_url(const std::string& url, const std::string& where);
  void validate() const;
};

class HttpRobotLink : public RobotLink {
 public:
  explicit HttpRobotLink(const RobotLinkOptions& options);
  ~HttpRobotLink() override;  // stops
  HttpRobotLink(const HttpRobotLink&) = delete;
  HttpRobotLink& operator=(const HttpRobotLink&) = delete;

  std::optional<LinkUpdate> next(std::chrono::milliseconds timeout) override;
  std::optional<LinkUpdate> latest(std::chrono::milliseconds timeout) override;

  /// POST /api/v1/navigation/ack.
  bool acknowledge(std::uint64_t seq) override;
  /// POST /api/v1/collected with the balls' positions.
  bool report_collected(const std::vector<Vec2>& positions, std::optional<int> held) override;
  /// POST /api/v1/unreachable.
  bool report_unreachable(const std::vector<Vec2>& positions, const std::string& reason) override;
  /// PUT /api/v1/robot.
  bool set_pose(const Pose2D& pose) override;
  /// PUT /api/v1/sim/drive.
  std::optional<nlohmann::json> drive_simulated(std::uint64_t seq, double speed_mps,
                                                double turn_rate_dps) override;

  /// Any other request of API v1 ("GET", "/api/v1/health", body): the answer's JSON on 200,
  /// else nullopt (and last_error says why).
  std::optional<nlohmann::json> call(const std::string& method, const std::string& target,
                                     const nlohmann::json& body);

  LinkStatus status() const override;
  void stop() override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
