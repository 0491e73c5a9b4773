#include "ballsight/core/json_fields.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight {

nlohmann::json read_json_document(const std::filesystem::path& path) {
  nlohmann::json document =
      nlohmann::json::parse(read_file(path, kMaxDocumentBytes), nullptr, false);
  require(!document.is_discarded(), path.string(), "not valid JSON");
  return document;
}

const nlohmann::json& json_member(const nlohmann::json& object, const std::string& key,
                                  const std::string& where) {
  require(object.is_object(), where, "expected a JSON object");
  const auto it = object.find(key);
  require(it != object.end(), where + "." + key, "missing");
  return *it;
}

double json_number(const nlohmann::json& object, const std::string& key, const std::string& where) {
  const nlohmann::json& value = json_member(object, key, where);
  require(value.is_number() && std::isfinite(value.get<double>()), where + "." + key,
          "expected a finite number");
  return value.get<double>();
}

int json_int(const nlohmann::json& object, const std::string& key, const std::string& where,
             int min, int max) {
  const nlohmann::json& value = json_member(object, key, where);
  require(
      value.is_number_integer() && value.get<long long>() >= min && value.get<long long>() <= max,
      where + "." + key,
      "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return value.get<int>();
}

bool json_bool(const nlohmann::json& object, const std::string& key, const std::string& where) {
  const nlohmann::json& value = json_member(object, key, where);
  require(value.is_boolean(), where + "." + key, "expected true or false");
  return value.get<bool>();
}

std::string json_string(const nlohmann::json& object, const std::string& key,
                        const std::string& where) {
  const nlohmann::json& value = json_member(object, key, where);
  require(value.is_string(), where + "." + key, "expected a string");
  return value.get<std::string>();
}

void json_require_string(const nlohmann::json& object, const std::string& key,
                         const std::string& where, const std::string& expected) {
  require(json_string(object, key, where) == expected, where + "." + key,
          "expected \"" + expected + "\"");
}

std::vector<double> json_number_array(const nlohmann::json& value, const std::string& where,
                                      std::size_t size) {
  const std::string expected =
      size == 0 ? std::string("expected an array of finite numbers")
                : "expected an array of " + std::to_string(size) + " finite numbers";
  require(value.is_array() && (size == 0 || value.size() == size), where, expected);
  std::vector<double> numbers;
  numbers.reserve(value.size());
  for (const nlohmann::json& element : value) {
    require(element.is_number() && std::isfinite(element.get<double>()), where, expected);
    numbers.push_back(element.get<double>());
  }
  return numbers;
}

std::vector<double> json_numbers(const nlohmann::json& object, const std::string& key,
                                 const std::string& where, std::size_t size) {
  return json_number_array(json_member(object, key, where), where + "." + key, size);
}

nlohmann::json pose_json(const Pose2D& pose) {
  return {{"x_m", pose.position.x()},
          {"y_m", pose.position.y()},
          {"heading_deg", deg_from_rad(pose.heading_rad)}};
}

Pose2D json_pose(const nlohmann::json& value, const std::string& where) {
  return {Vec2(json_number(value, "x_m", where), json_number(value, "y_m", where)),
          rad_from_deg(json_number(value, "heading_deg", where))};
}

std::optional<Pose2D> json_pose_if_any(const nlohmann::json& object, const std::string& key) {
  if (!object.is_object() || !object.contains(key)) return std::nullopt;
  try {
    return json_pose(object[key], key);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace ballsight
