#include "ballsight/pipeline/route_json.hpp"

namespace ballsight {
namespace {

nlohmann::json points(const std::vector<Vec2>& list) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec2& p : list) out.push_back({p.x(), p.y()});
  return out;
}

}  // namespace

nlohmann::json route_json(const Route& route) {
  return {{"planner", route.planner},
          {"order", route.order},
          {"visits_m", points(route.visits_m)},
          {"waypoints_m", points(route.waypoints_m)},
          {"unload_after", route.unload_after},
          {"unload_m", route.unload_m
                           ? nlohmann::json::array({route.unload_m->x(), route.unload_m->y()})
                           : nlohmann::json(nullptr)},
          {"unreachable", route.unreachable},
          {"length_m", route.length_m},
          {"time_s", route.time_s},
          {"plan_ms", route.plan_ms}};
}

}  // namespace ballsight
