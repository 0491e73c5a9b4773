#include "ballsight/service/navigation_json.hpp"

#include "ballsight/pipeline/route_json.hpp"
#include "ballsight/pipeline/world_model_json.hpp"

namespace ballsight {

nlohmann::json navigation_json(const NavigationUpdate& update, const std::string& service_id,
                               const std::vector<std::string>& camera_names) {
  nlohmann::json given_up = nlohmann::json::array();
  for (const UnreachableMark& m : update.given_up) {
    given_up.push_back(
        {{"x_m", m.position_m.x()}, {"y_m", m.position_m.y()}, {"reason", m.reason}});
  }
  return {{"seq", update.seq},
          {"service_id", service_id},
          {"capture_time_ns", update.capture_time_ns},
          {"published_ns", update.published_ns},
          {"world", world_model_json(update.world, camera_names)},
          {"route", route_json(update.route)},
          {"given_up", given_up}};
}

}  // namespace ballsight
