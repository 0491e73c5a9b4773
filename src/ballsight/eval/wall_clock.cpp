#include "ballsight/eval/wall_clock.hpp"

#include <vector>

namespace ballsight {
namespace {

// Object keys all the way (a json_pointer would make "12" an array index).
void move_timed(nlohmann::json& node, std::vector<std::string>& path,
                const std::set<std::string>& names, nlohmann::json& wall_clock) {
  if (!node.is_object()) return;
  std::vector<std::string> timed;
  for (auto& [key, value] : node.items()) {
    if (names.count(key) != 0) {
      timed.push_back(key);
      continue;
    }
    path.push_back(key);
    move_timed(value, path, names, wall_clock);
    path.pop_back();
  }
  for (const std::string& key : timed) {
    nlohmann::json* at = &wall_clock;
    for (const std::string& step : path) at = &(*at)[step];
    (*at)[key] = std::move(node[key]);
    node.erase(key);
  }
}

}  // namespace

nlohmann::json with_wall_clock_apart(nlohmann::json doc, const std::set<std::string>& names) {
  nlohmann::json wall_clock = nlohmann::json::object();
  std::vector<std::string> path;
  move_timed(doc, path, names, wall_clock);
  doc["wall_clock"] = std::move(wall_clock);
  return doc;
}

}  // namespace ballsight
