#include "ballsight/sim/json_io.hpp"

#include <algorithm>
#include <limits>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {

Json json_vec2(const Vec2& v) {
  return Json::array({v.x(), v.y()});
}

Json json_vec3(const Vec3& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

Json json_optional_vec2(const std::optional<Vec2>& v) {
  return v ? json_vec2(*v) : Json(nullptr);
}

Json json_bgr(const cv::Vec3b& c) {
  return Json::array({c[0], c[1], c[2]});
}

namespace {

void append_text(const Json& j, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  const std::string close_pad(static_cast<std::size_t>(indent), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    std::size_t i = 0;
    for (const auto& [key, value] : j.items()) {
      out += pad + Json(key).dump() + ": ";
      append_text(value, indent + 2, out);
      out += ++i < j.size() ? ",\n" : "\n";
    }
    out += close_pad + "}";
  } else if (j.is_array() &&
             std::any_of(j.begin(), j.end(), [](const Json& e) { return e.is_structured(); })) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += pad;
      append_text(j[i], indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += close_pad + "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string json_text(const Json& document) {
  std::string text;
  append_text(document, 0, text);
  return text + "\n";
}

JsonReader::JsonReader(const Json& object, std::string path, std::string source)
    : object_(object), path_(std::move(path)), source_(std::move(source)) {
  require(object_.is_object(), source_, path_ + ": expected an object");
}

void JsonReader::require_that(bool ok, const std::string& key, const std::string& what) const {
  require(ok, source_, path_ + "." + key + ": " + what);
}

const Json& JsonReader::at(const std::string& key) const {
  const auto it = object_.find(key);
  require_that(it != object_.end(), key, "missing");
  return *it;
}

bool JsonReader::has(const std::string& key) const {
  return object_.contains(key);
}

double JsonReader::number(const std::string& key) const {
  const Json& v = at(key);
  require_that(v.is_number(), key, "expected a number");
  return v.get<double>();
}

int JsonReader::integer(const std::string& key) const {
  const Json& v = at(key);
  require_that(v.is_number_integer() && v.get<double>() >= std::numeric_limits<int>::min() &&
                   v.get<double>() <= std::numeric_limits<int>::max(),
               key, "expected an integer");
  return v.get<int>();
}

std::uint64_t JsonReader::unsigned_integer(const std::string& key) const {
  const Json& v = at(key);
  require_that(v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0), key,
               "expected a non-negative integer");
  return v.get<std::uint64_t>();
}

bool JsonReader::boolean(const std::string& key) const {
  const Json& v = at(key);
  require_that(v.is_boolean(), key, "expected true or false");
  return v.get<bool>();
}

Vec2 JsonReader::vec2(const std::string& key) const {
  const Json& v = at(key);
  require_that(v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number(), key,
               "expected [x, y]");
  return {v[0].get<double>(), v[1].get<double>()};
}

std::optional<Vec2> JsonReader::optional_vec2(const std::string& key) const {
  return at(key).is_null() ? std::nullopt : std::optional(vec2(key));
}

cv::Vec3b JsonReader::bgr(const std::string& key) const {
  const Json& v = at(key);
  const auto channel_ok = [](const Json& c) {
    return c.is_number_integer() && c.get<int>() >= 0 && c.get<int>() <= 255;
  };
  require_that(
      v.is_array() && v.size() == 3 && channel_ok(v[0]) && channel_ok(v[1]) && channel_ok(v[2]),
      key, "expected [b, g, r] in 0..255");
  return {v[0].get<uchar>(), v[1].get<uchar>(), v[2].get<uchar>()};
}

const Json& JsonReader::array(const std::string& key) const {
  const Json& v = at(key);
  require_that(v.is_array(), key, "expected an array");
  return v;
}

JsonReader JsonReader::object(const std::string& key) const {
  return {at(key), path_ + "." + key, source_};
}

JsonReader JsonReader::element(const Json& array, std::size_t index, const std::string& key) const {
  return {array.at(index), path_ + "." + key + "[" + std::to_string(index) + "]", source_};
}

}  // namespace ballsight::sim
