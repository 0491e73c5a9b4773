#pragma once
// JSON as compact text for the wire and for recordings.

#include <nlohmann/json.hpp>
#include <string>

namespace ballsight {

/// `j` as JSON text; bytes that are not UTF-8 (a client's, a camera's message) become U+FFFD
/// instead of an exception.
inline std::string json_text(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace ballsight
