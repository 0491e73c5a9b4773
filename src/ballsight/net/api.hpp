#pragma once
// API v1 of the navigation service, independent of the transport: one request in, one response
// out (docs/robot-link.md; the routes are listed by `openapi_document()`). The HTTP server
// (http_server.hpp) parses the wire and says whether the request carried the token; everything a
// client sends is checked here, and every bad request gets a 4xx with {"error", "where"}.

#include <atomic>
#include <chrono>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/field_rect.hpp"
#include "ballsight/net/navigation_hub.hpp"

namespace ballsight {

struct ApiRequest {
  std::string method;  // "GET", "PUT", "POST", ...
  std::string target;  // path and query, e.g. "/api/v1/navigation?after=3&timeout_ms=500"
  std::string body;
  bool authorized = false;  // carried the service's bearer token
};

struct ApiResponse {
  int status = 200;
  std::string body;  // JSON, or empty for 204
};

struct ApiContext {
  ApiContext(NavigationHub& hub_, std::vector<std::string> camera_names_)
      : hub(hub_), camera_names(std::move(camera_names_)) {}

  NavigationHub& hub;
  std::vector<std::string> camera_names;
  FieldRect area{{-19.5, -10.5}, {19.5, 10.5}};  // positions a client sends must lie in it
  std::function<nlohmann::json()> health;        // the service's health document
  std::chrono::milliseconds max_wait{30000};     // cap on a long-poll's timeout_ms
};

/// Answers one request. Never throws for anything a client sends.
ApiResponse handle_api(const ApiRequest& request, const ApiContext& context);

/// The WebSocket stream at /api/v1/stream[?after=SEQ]: every navigation update newer than SEQ in
/// order, one text message each, {"topic": "navigation", "dropped": N, "update": {...}} (N: updates
/// skipped because this client fell more than NavigationHub::kKept behind), until `send` fails
/// (the client left) or `stopping` is set.
void stream_updates(const ApiRequest& request, const ApiContext& context,
                    const std::function<bool(const std::string&)>& send,
                    const std::atomic<bool>& stopping);
/// Whether `target` is the stream, and why it must be refused before the upgrade (nullopt: fine).
bool is_stream_target(const std::string& target);
std::optional<ApiResponse> stream_refusal(const ApiRequest& request);

/// The OpenAPI 3 document of API v1.
const nlohmann::json& openapi_document();

/// The JSON of one update: {"seq", "capture_time_ns", "published_ns", "world": {...}, "route":
/// {...}}.
nlohmann::json navigation_json(const NavigationUpdate& update,
                               const std::vector<std::string>& camera_names);

}  // namespace ballsight
