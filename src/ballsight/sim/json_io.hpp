#pragma once
// JSON helpers for the simulators' truth files (nlohmann::ordered_json, keys kept in writing
// order): small writers for geometric values, a reader that names the key path in every error,
// and a compact indented text form.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "ballsight/core/geometry.hpp"

namespace ballsight::sim {

using Json = nlohmann::ordered_json;

Json json_vec2(const Vec2& v);                          // [x, y]
Json json_vec3(const Vec3& v);                          // [x, y, z]
Json json_optional_vec2(const std::optional<Vec2>& v);  // [x, y] or null
Json json_bgr(const cv::Vec3b& c);                      // [b, g, r]

/// Indented objects; an array of scalars on one line, other arrays one element per line; a final
/// newline. Much shorter than dump(2) for tables of numbers.
std::string json_text(const Json& document);

/// Reads the keys of one JSON object; every error is an InputError
/// "<source>: <path>.<key>: <what was expected>".
class JsonReader {
 public:
  /// Throws unless `object` is a JSON object.
  JsonReader(const Json& object, std::string path, std::string source);

  const Json& at(const std::string& key) const;  // any value; throws when missing
  bool has(const std::string& key) const;
  double number(const std::string& key) const;
  int integer(const std::string& key) const;
  std::uint64_t unsigned_integer(const std::string& key) const;
  bool boolean(const std::string& key) const;
  Vec2 vec2(const std::string& key) const;
  std::optional<Vec2> optional_vec2(const std::string& key) const;  // null -> nullopt
  cv::Vec3b bgr(const std::string& key) const;
  const Json& array(const std::string& key) const;
  JsonReader object(const std::string& key) const;
  JsonReader element(const Json& array, std::size_t index, const std::string& key) const;

  /// Throws "<source>: <path>.<key>: <what>" when `ok` is false.
  void require_that(bool ok, const std::string& key, const std::string& what) const;

 private:
  const Json& object_;
  std::string path_;
  std::string source_;
};

}  // namespace ballsight::sim
