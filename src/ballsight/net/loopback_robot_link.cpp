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

LoopbackServer::LoopbackServer(CourtService& service, NavigationHub& hub)
    : context(api_context(service, hub)),
      token(random_hex(32)),
      server(loopback_server(token), api_v1_routes(context)) {}

LoopbackRobotLink::LoopbackRobotLink(CourtService& service, NavigationHub& hub)
    : LoopbackServer(service, hub), HttpRobotLink(loopback_client(server.port(), token)) {}

LoopbackRobotLink::~LoopbackRobotLink() {
  stop();
}

void LoopbackRobotLink::stop() {
  HttpRobotLink::stop();
  server.stop();
}

}  // namespace ballsight
