#include "ballsight/eval/loop_replay_data.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/eval/plot_inputs.hpp"

namespace ballsight {
namespace {

// Centimetres and tenths of a degree are all a picture of the court can show.
double rounded(double value, double step) {
  return std::round(value / step) * step;
}

nlohmann::json point(const Vec2& p) {
  return {rounded(p.x(), 0.01), rounded(p.y(), 0.01)};
}

nlohmann::json pose(double time_s, const Pose2D& pose) {
  return {rounded(time_s, 0.01), rounded(pose.position.x(), 0.01), rounded(pose.position.y(), 0.01),
          rounded(deg_from_rad(pose.heading_rad), 0.1)};
}

}  // namespace

nlohmann::json loop_replay_json(const LoopTruth& truth) {
  const LoopMapInput map = loop_map_input(truth);
  nlohmann::json path = nlohmann::json::array({pose(0.0, truth.robot_start)});
  for (const TruthTick& t : truth.ticks) path.push_back(pose(t.world.time_s, t.world.robot));
  nlohmann::json balls = nlohmann::json::array();
  for (const LoopMapInput::Ball& b : map.balls) {
    nlohmann::json ball = point(b.position_m);
    ball.push_back(b.collected_s ? nlohmann::json(rounded(*b.collected_s, 0.01)) : nullptr);
    balls.push_back(std::move(ball));
  }
  nlohmann::json routes = nlohmann::json::array();
  const std::vector<Vec2>* last = nullptr;
  for (const LoopMapInput::PublishedRoute& r : map.routes) {
    if (last && *last == r.waypoints_m) continue;
    nlohmann::json waypoints = nlohmann::json::array();
    for (const Vec2& p : r.waypoints_m) waypoints.push_back(point(p));
    routes.push_back({rounded(r.time_s, 0.01), std::move(waypoints)});
    last = &r.waypoints_m;
  }
  return {{"duration_s", rounded(map.duration_s, 0.01)},
          {"path", path},
          {"balls", balls},
          {"routes", routes}};
}

}  // namespace ballsight
