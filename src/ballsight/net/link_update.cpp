#include "ballsight/net/link_update.hpp"

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

std::vector<Vec2> points(const json& list, const std::string& where) {
  require(list.is_array(), where, "expected a list of points");
  std::vector<Vec2> out;
  for (const json& p : list) {
    if (p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number()) {
      out.emplace_back(p[0].get<double>(), p[1].get<double>());
    } else if (p.is_object() && p.contains("x_m") && p.contains("y_m") && p["x_m"].is_number() &&
               p["y_m"].is_number()) {
      out.emplace_back(p["x_m"].get<double>(), p["y_m"].get<double>());
    } else {
      require(false, where, "expected [x, y] or {\"x_m\", \"y_m\"}");
    }
  }
  return out;
}

}  // namespace

LinkUpdate parse_link_update(const json& u) {
  require(u.is_object(), "update", "expected an object");
  const auto field = [&](const char* key) -> const json& {
    require(u.contains(key), std::string("update.") + key, "missing");
    return u[key];
  };
  LinkUpdate out;
  require(field("seq").is_number_unsigned(), "update.seq", "expected an unsigned integer");
  out.seq = u["seq"].get<std::uint64_t>();
  require(field("service_id").is_string(), "update.service_id", "expected a string");
  out.service_id = u["service_id"].get<std::string>();
  require(field("capture_time_ns").is_number_integer() && field("published_ns").is_number_integer(),
          "update", "expected integer capture_time_ns and published_ns");
  out.capture_time_ns = u["capture_time_ns"].get<std::int64_t>();
  out.published_ns = u["published_ns"].get<std::int64_t>();
  const json& world = field("world");
  require(world.is_object() && world.contains("balls"), "update.world", "expected balls");
  out.balls_m = points(world["balls"], "update.world.balls");
  if (world.contains("robot") && world["robot"].is_object()) {
    const json& r = world["robot"];
    require(r.contains("heading_deg") && r["heading_deg"].is_number(), "update.world.robot",
            "expected heading_deg");
    out.robot = Pose2D{points(json::array({r}), "update.world.robot")[0],
                       rad_from_deg(r["heading_deg"].get<double>())};
  }
  if (const auto obstacles = world.find("obstacles"); obstacles != world.end()) {
    const std::vector<Vec2> centers = points(*obstacles, "update.world.obstacles");
    for (std::size_t i = 0; i < centers.size(); ++i) {
      const json& o = (*obstacles)[i];
      const json radius = o.is_object() ? o.value("radius_m", json()) : json();
      require(radius.is_number() && radius.get<double>() >= 0.0,
              "update.world.obstacles[" + std::to_string(i) + "].radius_m",
              "expected a non-negative number");
      out.obstacles.push_back({centers[i], radius.get<double>()});
    }
  }
  const json& route = field("route");
  require(route.is_object() && route.contains("waypoints_m") && route.contains("visits_m"),
          "update.route", "expected waypoints_m and visits_m");
  out.waypoints_m = points(route["waypoints_m"], "update.route.waypoints_m");
  out.visits_m = points(route["visits_m"], "update.route.visits_m");
  if (const auto unloads = route.find("unload_after"); unloads != route.end()) {
    require(unloads->is_array(), "update.route.unload_after", "expected a list of integers");
    if (!unloads->empty() && unloads->front() == -1) {
      require(route.contains("unload_m"), "update.route.unload_m",
              "missing where the basket is emptied");
      out.unload_first_m = points(json::array({route["unload_m"]}), "update.route.unload_m")[0];
    }
  }
  return out;
}

}  // namespace ballsight
