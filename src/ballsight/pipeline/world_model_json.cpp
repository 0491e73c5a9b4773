#include "ballsight/pipeline/world_model_json.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"

namespace ballsight {

namespace {

nlohmann::json names(const std::vector<int>& cameras,
                     const std::vector<std::string>& camera_names) {
  nlohmann::json out = nlohmann::json::array();
  for (int c : cameras)
    out.push_back(c >= 0 && static_cast<size_t>(c) < camera_names.size()
                      ? nlohmann::json(camera_names[static_cast<size_t>(c)])
                      : nlohmann::json(c));
  return out;
}

}  // namespace

nlohmann::json world_model_json(const WorldModel& world,
                                const std::vector<std::string>& camera_names) {
  nlohmann::json j;
  j["cameras"] = names(world.cameras, camera_names);
  j["balls"] = nlohmann::json::array();
  for (const FusedBall& ball : world.balls) {
    j["balls"].push_back({{"x_m", ball.position_m.x()},
                          {"y_m", ball.position_m.y()},
                          {"sigma_m", std::sqrt(0.5 * ball.covariance_m2.trace())},
                          {"cameras", names(ball.cameras, camera_names)}});
  }
  j["sites"] = nlohmann::json::array();
  for (const CollectionSite& site : world.sites) {
    j["sites"].push_back({{"x_m", site.center_m.x()},
                          {"y_m", site.center_m.y()},
                          {"diameter_m", site.diameter_m},
                          {"balls", site.balls}});
  }
  j["obstacles"] = nlohmann::json::array();
  for (const FloorObstacle& o : world.obstacles) {
    nlohmann::json outline = nlohmann::json::array();
    for (const Vec2& p : o.outline_m) outline.push_back({p.x(), p.y()});
    j["obstacles"].push_back({{"x_m", o.center_m.x()},
                              {"y_m", o.center_m.y()},
                              {"radius_m", o.radius_m},
                              {"outline_m", outline},
                              {"cameras", names(o.cameras, camera_names)}});
  }
  if (world.robot) {
    const RobotPoseEstimate& r = *world.robot;
    j["robot"] = {{"x_m", r.pose.position.x()},
                  {"y_m", r.pose.position.y()},
                  {"heading_deg", deg_from_rad(r.pose.heading_rad)},
                  {"position_sigma_m", r.position_sigma_m},
                  {"heading_sigma_deg", deg_from_rad(r.heading_sigma_rad)},
                  {"front_cameras", names(r.front_cameras, camera_names)},
                  {"back_cameras", names(r.back_cameras, camera_names)}};
  } else {
    j["robot"] = nullptr;
  }
  return j;
}

nlohmann::json site_court_json(const SiteCourt& court) {
  return {{"length_m", court.length_m},
          {"width_m", court.width_m},
          {"area_length_m", court.area_length_m},
          {"area_width_m", court.area_width_m},
          {"net", court.net},
          {"net_posts_outside_m", court.net_posts_outside_m}};
}

}  // namespace ballsight
