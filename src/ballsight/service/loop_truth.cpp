#include "ballsight/service/loop_truth.hpp"

#include <fstream>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/sim/tennis_court.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

json points_json(const std::vector<Vec2>& points) {
  json out = json::array();
  for (const Vec2& p : points) out.push_back(json::array({p.x(), p.y()}));
  return out;
}

TruthTick tick_of(const json& j, const std::string& where) {
  TruthTick t;
  t.world.time_s = j.at("time_s").get<double>();
  t.world.robot = json_pose(j.at("robot"), where + ": robot");
  t.world.collected = j.at("collected").get<std::vector<int>>();
  t.world.balls_left = j.at("balls_left").get<int>();
  t.world.blocked = j.at("blocked").get<bool>();
  t.world.held = j.value("held", 0);  // absent from records written before the basket
  t.world.unloaded = j.value("unloaded", false);
  t.world.clearance_m = j.value("clearance_m", NAN);  // absent from records before obstacles
  t.seq = j.at("seq").get<std::uint64_t>();
  t.command.speed_mps = j.at("command").at("speed_mps").get<double>();
  t.command.turn_rate_rps = rad_from_deg(j.at("command").at("turn_rate_dps").get<double>());
  const json& p = j.at("published");
  if (!p.at("robot").is_null())
    t.published.robot = json_pose(p.at("robot"), where + ": published.robot");
  t.published.balls_seen = p.at("balls_seen").get<int>();
  t.removed_by_hand = j.at("removed_by_hand").get<std::vector<int>>();
  for (const json& w : p.at("waypoints_m")) {
    t.published.waypoints_m.emplace_back(w.at(0).get<double>(), w.at(1).get<double>());
  }
  return t;
}

}  // namespace

json scene_record(std::uint64_t seed, const std::vector<SceneBall>& balls, const Pose2D& robot) {
  json list = json::array();
  for (const SceneBall& b : balls) {
    list.push_back({{"id", b.id}, {"x_m", b.position_m.x()}, {"y_m", b.position_m.y()}});
  }
  return {{"kind", "scene"}, {"seed", seed}, {"balls", list}, {"robot", pose_json(robot)}};
}

json tick_record(const TruthTick& t) {
  json j = {{"kind", "tick"},
            {"time_s", t.world.time_s},
            {"seq", t.seq},
            {"robot", pose_json(t.world.robot)},
            {"command",
             {{"speed_mps", t.command.speed_mps},
              {"turn_rate_dps", deg_from_rad(t.command.turn_rate_rps)}}},
            {"collected", t.world.collected},
            {"balls_left", t.world.balls_left},
            {"blocked", t.world.blocked},
            {"held", t.world.held},
            {"unloaded", t.world.unloaded},
            {"published",
             {{"robot", t.published.robot ? pose_json(*t.published.robot) : json(nullptr)},
              {"balls_seen", t.published.balls_seen},
              {"waypoints_m", points_json(t.published.waypoints_m)}}},
            {"removed_by_hand", t.removed_by_hand}};
  if (!std::isnan(t.world.clearance_m)) j["clearance_m"] = t.world.clearance_m;
  return j;
}

json event_record(const TruthEvent& e) {
  return {{"kind", "event"}, {"time_s", e.time_s}, {"what", e.what}};
}

LoopTruth read_loop_truth(const std::filesystem::path& file) {
  std::ifstream in(file);
  require(in.good(), file.string(), "cannot open for reading");
  return parse_loop_truth(in, file.string());
}

LoopTruth parse_loop_truth(std::istream& in, const std::string& source) {
  LoopTruth truth;
  bool scene = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = source + ":" + std::to_string(number);
    if (line.empty()) continue;
    json j;
    try {
      j = json::parse(line);
    } catch (const json::exception& e) {
      if (in.eof()) break;  // a last line with no newline: cut short by a kill
      throw InputError(where + ": not JSON: " + e.what());
    }
    try {
      const std::string kind = j.at("kind").get<std::string>();
      if (kind == "scene") {
        require(!scene, where, "a second scene record");
        scene = true;
        truth.seed = j.at("seed").get<std::uint64_t>();
        for (const json& b : j.at("balls")) {
          truth.balls.push_back(
              {b.at("id").get<int>(), Vec2(b.at("x_m").get<double>(), b.at("y_m").get<double>())});
        }
        truth.robot_start = json_pose(j.at("robot"), where + ": robot");
      } else if (kind == "tick") {
        require(scene, where, "a tick before the scene record");
        truth.ticks.push_back(tick_of(j, where));
      } else if (kind == "event") {
        truth.events.push_back({j.at("time_s").get<double>(), j.at("what").get<std::string>()});
      } else {
        throw InputError(where + ": unknown kind '" + kind + "' (scene, tick, event)");
      }
    } catch (const json::exception& e) {
      throw InputError(where + ": " + e.what());
    }
  }
  require(scene, source, "has no scene record (is it a serve --sim --truth-out file?)");
  return truth;
}

LoopScore score_loop(const LoopTruth& truth, const sim::RobotFootprint& footprint) {
  std::vector<sim::WorldTick> ticks;
  for (const TruthTick& t : truth.ticks) ticks.push_back(t.world);
  return score_loop(static_cast<int>(truth.balls.size()), truth.robot_start, ticks, footprint);
}

sim::RobotFootprint collector_footprint(const SiteRobot& robot) {
  return sim::RobotFootprint::of(sim::RobotBox{}, robot.collector_x_m, robot.collector_width_m);
}

void drop_unfinished_line(const std::filesystem::path& file) {
  const std::string text = read_file(file);
  if (text.empty() || text.back() == '\n') return;
  const std::size_t end = text.rfind('\n');
  std::filesystem::resize_file(file, end == std::string::npos ? 0 : end + 1);
}

LoopScore score_loop(int balls, const Pose2D& start, const std::vector<sim::WorldTick>& ticks,
                     const sim::RobotFootprint& footprint) {
  LoopScore score;
  score.balls = balls;
  const sim::TennisCourtSpec court;
  Vec2 last = start.position;
  for (const sim::WorldTick& t : ticks) {
    score.distance_m += (t.robot.position - last).norm();
    last = t.robot.position;
    score.collected += static_cast<int>(t.collected.size());
    score.blocked_ticks += t.blocked ? 1 : 0;
    score.unloads += t.unloaded ? 1 : 0;
    score.min_clearance_m =
        std::min(score.min_clearance_m, std::isnan(t.clearance_m)
                                            ? sim::footprint_clearance(footprint, t.robot, court)
                                            : t.clearance_m);
    score.never_overlapped = score.never_overlapped && score.min_clearance_m > 0.0;
    score.time_s = t.time_s;
    if (t.balls_left == 0) {
      score.all = true;
      break;
    }
  }
  return score;
}

}  // namespace ballsight
