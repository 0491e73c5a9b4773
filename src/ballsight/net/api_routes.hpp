#pragma once
// What passes between the transport (http_server.hpp) and the API modules (API v1, api.hpp; the
// calibration pages' APIs, calibration/): a request, its answer, and the routes by which a module
// says which requests are its own. The transport parses the wire and asks the routes; it names no
// API.

#include <chrono>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ballsight {

struct ApiRequest {
  std::string method;  // "GET", "PUT", "POST", ...
  std::string target;  // path and query, e.g. "/api/v1/navigation?after=3&timeout_ms=500"
  std::string body;
  bool authorized = false;  // carried the service's bearer token
};

struct ApiResponse {
  ApiResponse(int status_ = 200, std::string body_ = {})
      : status(status_), body(std::move(body_)) {}

  int status;
  std::string body;  // JSON (or a web page's file: content_type), or empty for 204
  std::string content_type = "application/json";
  /// A long-poll with nothing newer than `wait_after` yet: the transport waits up to `wait` for
  /// an update, then answers with API v1's `poll_answer` (api.hpp; 204 when none came). Empty:
  /// answer now.
  std::optional<std::uint64_t> wait_after;
  std::chrono::milliseconds wait{0};
};

/// `j` as JSON text; bytes that are not UTF-8 (a client's, a camera's message) become U+FFFD
/// instead of an exception.
std::string json_text(const nlohmann::json& j);

/// The 4xx/5xx answer {"error": what, "where": where}.
ApiResponse api_error(int status, const std::string& what, const std::string& where);

/// The requests an API module answers: those whose path starts with `prefix`.
struct ApiModuleRoute {
  std::string prefix;  // starts and ends with '/', so that it matches whole path segments
  /// Answers one request; never throws for anything a client sends.
  std::function<ApiResponse(const ApiRequest&)> handler;
  /// Its answers take more than a moment (a calibration step, a frame encoded): the transport
  /// answers them off its I/O thread, so that they hold up no other client.
  bool runs_long = false;
};

/// The routes the API modules registered. A request goes to the route of the longest prefix its
/// path starts with, so that a module may take a part of another's URLs (/api/v1/omni/ inside
/// /api/v1/). Filled before serving, then only read (from any thread).
class ApiRoutes {
 public:
  /// Throws InputError when the prefix does not start and end with '/', another route has it
  /// already, or the handler is empty.
  void add(ApiModuleRoute route);
  /// The answer of the request's route; a 404 {"error": "unknown route", "where": PATH} when no
  /// route takes it.
  ApiResponse answer(const ApiRequest& request) const;
  /// Whether the route of `target` (path and query) runs long; false when no route takes it.
  bool runs_long(const std::string& target) const;

 private:
  /// The route of the longest prefix `target`'s path starts with; null when none.
  const ApiModuleRoute* route_of(const std::string& target) const;

  std::vector<ApiModuleRoute> routes_;  // longest prefix first
};

}  // namespace ballsight
