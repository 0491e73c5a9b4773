#pragma once
// Reading fields of a JSON document with errors that name the field's path and what was
// expected (InputError "<where>.<key>: expected ...").

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

/// The JSON document of a file of at most kMaxDocumentBytes (file_io.hpp); throws InputError
/// naming the file when it cannot be read or is not valid JSON.
nlohmann::json read_json_document(const std::filesystem::path& path);

/// The object member `key`; throws when `object` is not an object or lacks it.
const nlohmann::json& json_member(const nlohmann::json& object, const std::string& key,
                                  const std::string& where);
/// A finite number.
double json_number(const nlohmann::json& object, const std::string& key, const std::string& where);
/// An integer in [min, max].
int json_int(const nlohmann::json& object, const std::string& key, const std::string& where,
             int min, int max);
/// A boolean.
bool json_bool(const nlohmann::json& object, const std::string& key, const std::string& where);
/// A string.
std::string json_string(const nlohmann::json& object, const std::string& key,
                        const std::string& where);
/// Throws unless the member `key` is the string `expected`.
void json_require_string(const nlohmann::json& object, const std::string& key,
                         const std::string& where, const std::string& expected);
/// `value` as an array of finite numbers, of `size` elements unless size is 0.
std::vector<double> json_number_array(const nlohmann::json& value, const std::string& where,
                                      std::size_t size = 0);
/// The member `key` as an array of finite numbers, of `size` elements unless size is 0.
std::vector<double> json_numbers(const nlohmann::json& object, const std::string& key,
                                 const std::string& where, std::size_t size = 0);

/// A pose as {"x_m", "y_m", "heading_deg"}.
nlohmann::json pose_json(const Pose2D& pose);
/// The pose `value` ({"x_m", "y_m", "heading_deg"}, finite numbers).
Pose2D json_pose(const nlohmann::json& value, const std::string& where);
/// The member `key` of `object` as a pose; nullopt when it is missing or not one (a reading
/// that is to be skipped, not refused).
std::optional<Pose2D> json_pose_if_any(const nlohmann::json& object, const std::string& key);

}  // namespace ballsight
