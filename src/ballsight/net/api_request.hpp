#pragma once
// Reading a request of the service's API modules (api.hpp, calibration/): its path and query,
// its JSON body, and the client mistakes that become 4xx answers {"error", "where"}.

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/net/api_routes.hpp"

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

/// The segments of `path` after `prefix` (which it starts with), each percent-decoded:
/// ("/api/v1/omni/fits/3", "/api/v1/omni/") -> {"fits", "3"}.
std::vector<std::string> path_parts(const std::string& path, std::string_view prefix);

/// A route of an API under a prefix, by its path segments: `size` segments, the first `first`,
/// the last `last` (when given; the ones between are ids), taken by `method`.
struct SegmentRoute {
  std::size_t size;
  const char* first;
  const char* last;
  const char* method;
  std::function<ApiResponse()> answer;
};

/// The answer of the route `parts` match; a 405 when it does not take the request's method, a 404
/// when none matches (both ApiErrors).
ApiResponse dispatch(const ApiRequest& request, const std::vector<std::string>& parts,
                     const std::vector<SegmentRoute>& routes);

/// `text` with its %XX escapes and '+' (a browser's URLSearchParams) decoded; a '%' that does
/// not start an escape stays as it is.
std::string percent_decoded(const std::string& text);

/// A 401 ApiError unless the request carried the service's token (a write).
void require_write(const ApiRequest& request);

/// The value of `key` in the query, one of `choices` (the first when absent); a 400 ApiError
/// naming the choices otherwise.
std::string query_choice(const std::string& query, const std::string& key,
                         const std::vector<std::string>& choices);

/// The item of `items` (pointers to objects with an `id`) whose id reads `id`; a 404 ApiError
/// `what` at "`name` `id`" when there is none.
template <class Items>
typename Items::value_type item_by_id(const Items& items, const std::string& id,
                                      const std::string& name, const std::string& what) {
  for (const auto& item : items)
    if (std::to_string(item->id) == id) return item;
  api_fail(404, what, name + " " + id);
}

/// `answer()`, or the answer to what it threw: a client's mistake (ApiError, InputError: 422) its
/// 4xx, anything else a 500 (server_error). Never throws.
ApiResponse answer_or_error(const std::function<ApiResponse()>& answer);

/// An InputError's "where: what" as the answer {"error": what, "where": where}.
ApiResponse input_error(int status, const InputError& e);
/// A failure that is not the client's (a file that cannot be written, a library's exception): a
/// 500 {"error": what, "where": "server"}, written to stderr too.
ApiResponse server_error(const std::exception& e);
/// `body` as a JSON answer of `status`.
ApiResponse json_answer(int status, const nlohmann::json& body);
/// A 200 answer of other bytes (an image, a file to download).
ApiResponse bytes_answer(std::string bytes, const std::string& content_type);

/// The body as a JSON object; a 400 ApiError when it is malformed or not an object.
nlohmann::json parse_body(const std::string& body);

/// The value of `key` in the query "a=1&b=2" (its %XX escapes and '+' decoded, as a browser's
/// URLSearchParams and encodeURIComponent write them), or nullopt when absent.
std::optional<std::string> query_text(const std::string& query, const std::string& key);

}  // namespace ballsight
