#include "ballsight/net/api_routes.hpp"

#include <algorithm>

#include "ballsight/core/error.hpp"
#include "ballsight/net/api_request.hpp"

namespace ballsight {

ApiResponse api_error(int status, const std::string& what, const std::string& where) {
  return {status, json_text(nlohmann::json{{"error", what}, {"where", where}})};
}

void ApiRoutes::add(ApiModuleRoute route) {
  const std::string where = "API route '" + route.prefix + "'";
  require(!route.prefix.empty() && route.prefix.front() == '/' && route.prefix.back() == '/', where,
          "a prefix starts and ends with '/'");
  require(static_cast<bool>(route.handler), where, "has no handler");
  // Two modules on one prefix: which one answers would depend on the order they registered in.
  require(std::none_of(routes_.begin(), routes_.end(),
                       [&](const ApiModuleRoute& r) { return r.prefix == route.prefix; }),
          where, "registered twice");
  const auto longer = [](const ApiModuleRoute& a, const ApiModuleRoute& b) {
    return a.prefix.size() > b.prefix.size();
  };
  routes_.insert(std::upper_bound(routes_.begin(), routes_.end(), route, longer), std::move(route));
}

const ApiModuleRoute* ApiRoutes::route_of(const std::string& target) const {
  const std::string path = split_target(target).path;
  const auto route = std::find_if(routes_.begin(), routes_.end(), [&](const ApiModuleRoute& r) {
    return path.starts_with(r.prefix);
  });
  return route == routes_.end() ? nullptr : &*route;
}

ApiResponse ApiRoutes::answer(const ApiRequest& request) const {
  if (const ApiModuleRoute* route = route_of(request.target)) return route->handler(request);
  return api_error(404, "unknown route", split_target(request.target).path);
}

bool ApiRoutes::runs_long(const std::string& target) const {
  const ApiModuleRoute* route = route_of(target);
  return route && route->runs_long;
}

void ApiRoutes::add_websocket(WebSocketOpener opener) {
  require(static_cast<bool>(opener), "WebSocket opener", "is empty");
  openers_.push_back(std::move(opener));
}

std::variant<WebSocketOpened, ApiResponse> ApiRoutes::open_websocket(
    const ApiRequest& request, const std::string& subprotocols) const {
  for (const WebSocketOpener& open : openers_)
    if (auto opened = open(request, subprotocols)) return std::move(*opened);
  return api_error(404, "no WebSocket here", split_target(request.target).path);
}

}  // namespace ballsight
