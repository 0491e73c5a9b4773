#include "ballsight/net/loopback_robot_link.hpp"

#include "ballsight/net/service_api.hpp"

namespace ballsight {
namespace {

HttpServerOptions loopback_server(const std::string& token) {
  HttpServerOptions options;
  options.port = 0;
  options.token = token;
  return options;
}

RobotLinkOptions loopback_client(unsigned short port, const std::string& token) {
  RobotLinkOptions options;
  options.port = port;
  options.token = token;
  return options;
}

}  // namespace

LoopbackRobotLink::LoopbackRobotLink(CourtService& service, NavigationHub& hub)
    : context_(api_context(service, hub)),
      token_(random_hex(32)),
      server_(loopback_server(token_), context_),
      link_(loopback_client(server_.port(), token_)) {}

LoopbackRobotLink::~LoopbackRobotLink() {
  stop();
}

std::optional<LinkUpdate> LoopbackRobotLink::next(std::chrono::milliseconds timeout) {
  return link_.next(timeout);
}

std::optional<LinkUpdate> LoopbackRobotLink::latest(std::chrono::milliseconds timeout) {
  return link_.latest(timeout);
}

bool LoopbackRobotLink::acknowledge(std::uint64_t seq) {
  return link_.acknowledge(seq);
}

bool LoopbackRobotLink::report_collected(const std::vector<Vec2>& positions) {
  return link_.report_collected(positions);
}

bool LoopbackRobotLink::set_pose(const Pose2D& pose) {
  return link_.set_pose(pose);
}

std::optional<nlohmann::json> LoopbackRobotLink::drive_simulated(std::uint64_t seq,
                                                                 double speed_mps,
                                                                 double turn_rate_dps) {
  return link_.drive_simulated(seq, speed_mps, turn_rate_dps);
}

LinkStatus LoopbackRobotLink::status() const {
  return link_.status();
}

void LoopbackRobotLink::stop() {
  link_.stop();
  server_.stop();
}

}  // namespace ballsight
