// API v1's request handling (net/api.cpp) on arbitrary requests: the first line of the input is
// the method, the second the target, the rest the body; the first byte's low bit says whether the
// request carried the token. Every answer must be a 2xx/4xx/5xx with a JSON body (or an empty
// 204), and nothing may throw. The stream's subscription parser gets the same target.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "ballsight/net/api.hpp"

namespace {

using namespace ballsight;

NavigationUpdate some_update() {
  NavigationUpdate u;
  u.capture_time_ns = 1;
  RobotPoseEstimate robot;
  robot.pose = {Vec2(1.0, 2.0), 0.5};
  u.world.robot = robot;
  u.world.balls.push_back({Vec2(3, 4), Eigen::Matrix2d::Zero(), {0}});
  u.route.waypoints_m = {Vec2(1, 2), Vec2(3, 4)};
  return u;
}

void check(const ApiResponse& r) {
  if (r.status < 200 || r.status > 599) std::abort();
  if (r.body.empty()) {
    if (r.status != 204) std::abort();
    return;
  }
  if (nlohmann::json::parse(r.body, nullptr, false).is_discarded()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static NavigationHub hub;
  static ApiContext context = [] {
    ApiContext c(hub, {"ne", "se", "sw", "nw"}, SiteCourt{}, 0.0335);
    c.health = [] { return nlohmann::json{{"ok", true}}; };
    return c;
  }();
  if (!hub.latest()) hub.publish(some_update());
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t first = input.find('\n');
  const std::size_t second = first == std::string::npos ? first : input.find('\n', first + 1);
  ApiRequest request;
  request.method = input.substr(0, first);
  if (first != std::string::npos) request.target = input.substr(first + 1, second - first - 1);
  if (second != std::string::npos) request.body = input.substr(second + 1);
  request.authorized = size > 0 && (data[0] & 1) != 0;
  const ApiResponse response = handle_api(request, context);
  check(response);
  if (response.retry) {
    if (const std::optional<ApiResponse> answer = response.retry()) check(*answer);
  }
  const auto subscription = stream_subscription(request, context);
  if (const auto* refusal = std::get_if<ApiResponse>(&subscription)) check(*refusal);
  return 0;
}
