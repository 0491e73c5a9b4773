#pragma once
// A robot link to a court service of this process, the way a robot reaches it on court: API v1
// over HTTP and WebSocket on a free loopback port, with a fresh token (`eval loop`, benches,
// tests). It owns the server; stopping the link stops both.

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "ballsight/net/api.hpp"
#include "ballsight/net/http_robot_link.hpp"
#include "ballsight/net/http_server.hpp"
#include "ballsight/robot/robot_link.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight {

class LoopbackRobotLink : public RobotLink {
 public:
  /// `service` and `hub` must outlive the link.
  LoopbackRobotLink(CourtService& service, NavigationHub& hub);
  ~LoopbackRobotLink() override;

  std::optional<LinkUpdate> next(std::chrono::milliseconds timeout) override;
  std::optional<LinkUpdate> latest(std::chrono::milliseconds timeout) override;
  bool acknowledge(std::uint64_t seq) override;
  bool report_collected(const std::vector<Vec2>& positions) override;
  bool set_pose(const Pose2D& pose) override;
  std::optional<nlohmann::json> drive_simulated(std::uint64_t seq, double speed_mps,
                                                double turn_rate_dps) override;
  LinkStatus status() const override;
  /// Stops the client, then the server.
  void stop() override;

 private:
  ApiContext context_;
  std::string token_;
  HttpServer server_;
  HttpRobotLink link_;
};

}  // namespace ballsight
