#include "ballsight/net/api_request.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>

namespace ballsight {

std::string percent_decoded(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    unsigned value = 0;
    if (text[i] == '%' && i + 2 < text.size() &&
        std::from_chars(text.data() + i + 1, text.data() + i + 3, value, 16).ptr ==
            text.data() + i + 3) {
      out += static_cast<char>(value);
      i += 2;
    } else {
      out += text[i] == '+' ? ' ' : text[i];
    }
  }
  return out;
}

ApiResponse error_response(const ApiError& e) {
  return api_error(e.status, e.what, e.where);
}

void api_fail(int status, const std::string& what, const std::string& where) {
  throw ApiError{status, what, where};
}

nlohmann::json parse_body(const std::string& body) {
  nlohmann::json j = nlohmann::json::parse(body, nullptr, false);
  if (j.is_discarded()) api_fail(400, "malformed JSON", "body");
  if (!j.is_object()) api_fail(400, "expected a JSON object", "body");
  return j;
}

std::optional<std::string> query_text(const std::string& query, const std::string& key) {
  std::size_t start = 0;
  while (start < query.size()) {
    const std::size_t end = std::min(query.find('&', start), query.size());
    const std::string item = query.substr(start, end - start);
    const std::size_t eq = item.find('=');
    if (percent_decoded(item.substr(0, eq)) == key)
      return eq == std::string::npos ? "" : percent_decoded(item.substr(eq + 1));
    start = end + 1;
  }
  return std::nullopt;
}

std::vector<std::string> path_parts(const std::string& path, std::string_view prefix) {
  std::vector<std::string> parts;
  for (std::size_t start = prefix.size(); start <= path.size();) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    parts.push_back(percent_decoded(path.substr(start, end - start)));
    start = end + 1;
  }
  return parts;
}

ApiResponse dispatch(const ApiRequest& request, const std::vector<std::string>& parts,
                     const std::vector<SegmentRoute>& routes) {
  for (const SegmentRoute& r : routes) {
    if (parts.size() != r.size || parts[0] != r.first || (r.last && parts.back() != r.last))
      continue;
    if (request.method != r.method)
      api_fail(405, "method " + request.method + " not allowed", split_target(request.target).path);
    return r.answer();
  }
  api_fail(404, "unknown route", split_target(request.target).path);
}

void require_write(const ApiRequest& request) {
  if (!request.authorized) api_fail(401, "writes need 'Authorization: Bearer TOKEN'", "headers");
}

std::string query_choice(const std::string& query, const std::string& key,
                         const std::vector<std::string>& choices) {
  const std::string value = query_text(query, key).value_or(choices.front());
  if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i)
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  api_fail(400, "expected " + list + ", got '" + value + "'", "query " + key);
}

ApiResponse answer_or_error(const std::function<ApiResponse()>& answer) {
  try {
    return answer();
  } catch (const ApiError& e) {
    return error_response(e);
  } catch (const InputError& e) {
    return input_error(422, e);
  } catch (const std::exception& e) {
    return server_error(e);
  }
}

ApiResponse input_error(int status, const InputError& e) {
  const std::string message = e.what();
  const std::size_t colon = message.find(": ");
  if (colon == std::string::npos) return api_error(status, message, "body");
  return api_error(status, message.substr(colon + 2), message.substr(0, colon));
}

ApiResponse server_error(const std::exception& e) {
  std::cerr << "ballsight serve: " << e.what() << "\n";
  return api_error(500, e.what(), "server");
}

ApiResponse json_answer(int status, const nlohmann::json& body) {
  return {status, json_text(body)};
}

ApiResponse bytes_answer(std::string bytes, const std::string& content_type) {
  ApiResponse r(200, std::move(bytes));
  r.content_type = content_type;
  return r;
}

RequestTarget split_target(const std::string& target) {
  const std::size_t q = target.find('?');
  return {target.substr(0, q), q == std::string::npos ? "" : target.substr(q + 1)};
}

}  // namespace ballsight
