#pragma once
// A robot link to a court service of this process, the way a robot reaches it on court: API v1
// over HTTP and WebSocket on a free loopback port, with a fresh token (`eval loop`, benches,
// tests). It is an HttpRobotLink that owns its server; stopping the link stops both.

#include <string>

#include "ballsight/net/api.hpp"
#include "ballsight/net/http_robot_link.hpp"
#include "ballsight/net/http_server.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight {

/// The server side, a base so that it is built before the client and outlives it.
struct LoopbackServer {
  LoopbackServer(CourtService& service, NavigationHub& hub);

  ApiContext context;
  std::string token;
  HttpServer server;
};

class LoopbackRobotLink : private LoopbackServer, public HttpRobotLink {
 public:
  /// `service` and `hub` must outlive the link.
  LoopbackRobotLink(CourtService& service, NavigationHub& hub);
  ~LoopbackRobotLink() override;

  /// Stops the client, then the server.
  void stop() override;
};

}  // namespace ballsight
