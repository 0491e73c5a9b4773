#include "ballsight/service/navigation_json.hpp"

#include "ballsight/pipeline/route_json.hpp"
#include "ballsight/pipeline/world_model_json.hpp"

namespace ballsight {

namespace {

nlohmann::json marks_json(const std::vector<UnreachableMark>& marks) {
  nlohmann::json out = nlohmann::json::array();
  for (const UnreachableMark& m : marks) {
    out.push_back({{"x_m", m.position_m.x()}, {"y_m", m.position_m.y()}, {"reason", m.reason}});
  }
  return out;
}

}  // namespace

nlohmann::json navigation_json(const NavigationUpdate& update, const std::string& service_id,
                               const std::vector<std::string>& camera_names) {
  return {{"seq", update.seq},
          {"service_id", service_id},
          {"capture_time_ns", update.capture_time_ns},
          {"published_ns", update.published_ns},
          {"world", world_model_json(update.world, camera_names)},
          {"route", route_json(update.route)},
          {"given_up", marks_json(update.given_up)}};
}

nlohmann::json client_reports_json(const ClientReports& reports) {
  nlohmann::json out{{"robot", nullptr},
                     {"balls", nullptr},
                     {"collected", nlohmann::json::array()},
                     {"basket", nullptr},
                     {"unreachable", marks_json(reports.unreachable)}};
  if (reports.robot) {
    const Pose2D& p = reports.robot->value;
    out["robot"] = {{"x_m", p.position.x()},
                    {"y_m", p.position.y()},
                    {"heading_rad", p.heading_rad},
                    {"set_ns", reports.robot->set_ns}};
  }
  if (reports.balls) {
    out["balls"] = {{"count", reports.balls->value.size()}, {"set_ns", reports.balls->set_ns}};
  }
  for (const Vec2& c : reports.collected) out["collected"].push_back({c.x(), c.y()});
  if (reports.basket) {
    out["basket"] = {{"held", reports.basket->value}, {"set_ns", reports.basket->set_ns}};
  }
  return out;
}

}  // namespace ballsight
