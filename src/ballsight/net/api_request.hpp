#pragma once
// Reading a request of the service's APIs (api.hpp, omni_calibration_api.hpp): its path and query,
// its JSON body, and the client mistakes that become 4xx answers {"error", "where"}.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "ballsight/net/api.hpp"

namespace ballsight {

/// A client's mistake: the status to answer with, what is wrong and where.
struct ApiError {
  int status;
  std::string what;
  std::string where;
};

/// Throws ApiError{status, what, where}.
[[noreturn]] void api_fail(int status, const std::string& what, const std::string& where);

/// The answer to an ApiError.
ApiResponse error_response(const ApiError& e);

/// A request target split at its '?': "/api/v1/x?a=1" -> {"/api/v1/x", "a=1"}.
struct RequestTarget {
  std::string path;
  std::string query;
};
RequestTarget split_target(const std::string& target);

/// The body as a JSON object; a 400 ApiError when it is malformed or not an object.
nlohmann::json parse_body(const std::string& body);

/// The value of `key` in the query "a=1&b=2" (its %XX escapes and '+' decoded, as a browser's
/// URLSearchParams and encodeURIComponent write them), or nullopt when absent.
std::optional<std::string> query_text(const std::string& query, const std::string& key);

}  // namespace ballsight
