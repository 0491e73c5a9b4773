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
          {"given_up", marks_json(update.reports.unreachable)}};
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
    nlohmann::json m = nlohmann::json::array();
    for (const Vec2& b : reports.balls->value) m.push_back({b.x(), b.y()});
    out["balls"] = {{"count", reports.balls->value.size()},
                    {"m", std::move(m)},
                    {"set_ns", reports.balls->set_ns}};
  }
  for (const Vec2& c : reports.collected) out["collected"].push_back({c.x(), c.y()});
  if (reports.basket) {
    out["basket"] = {{"held", reports.basket->value}, {"set_ns", reports.basket->set_ns}};
  }
  return out;
}

ClientReports parse_client_reports(const nlohmann::json& json) {
  const auto point = [](const nlohmann::json& p) {
    return Vec2(p.at(0).get<double>(), p.at(1).get<double>());
  };
  ClientReports reports;
  if (const nlohmann::json& r = json.at("robot"); !r.is_null()) {
    reports.robot = {
        {{r.at("x_m").get<double>(), r.at("y_m").get<double>()}, r.at("heading_rad").get<double>()},
        r.at("set_ns").get<std::int64_t>()};
  }
  if (const nlohmann::json& b = json.at("balls"); !b.is_null()) {
    reports.balls = {{}, b.at("set_ns").get<std::int64_t>()};
    for (const nlohmann::json& p : b.at("m")) reports.balls->value.push_back(point(p));
  }
  for (const nlohmann::json& p : json.at("collected")) reports.collected.push_back(point(p));
  if (const nlohmann::json& b = json.at("basket"); !b.is_null()) {
    reports.basket = {b.at("held").get<int>(), b.at("set_ns").get<std::int64_t>()};
  }
  for (const nlohmann::json& m : json.at("unreachable")) {
    reports.unreachable.push_back({{m.at("x_m").get<double>(), m.at("y_m").get<double>()},
                                   m.at("reason").get<std::string>()});
  }
  return reports;
}

}  // namespace ballsight
