#include "ballsight/service/run_replay.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/closest_pairs.hpp"
#include "ballsight/service/navigation_json.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

/// A replayed ball this far from every recorded one is another ball.
constexpr double kMatchM = 0.5;

std::vector<Vec2> ball_positions(const json& navigation) {
  std::vector<Vec2> balls;
  for (const json& b : navigation.at("world").at("balls"))
    balls.emplace_back(b.at("x_m").get<double>(), b.at("y_m").get<double>());
  return balls;
}

bool route_changed(const json& recorded, const json& replayed) {
  if (recorded.at("order") != replayed.at("order")) return true;
  const json& a = recorded.at("waypoints_m");
  const json& b = replayed.at("waypoints_m");
  if (a.size() != b.size()) return true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 p(a[i].at(0).get<double>(), a[i].at(1).get<double>());
    const Vec2 q(b[i].at(0).get<double>(), b[i].at(1).get<double>());
    if ((p - q).norm() > kReplayMovedM) return true;
  }
  return false;
}

/// Compares a replayed update's navigation JSON with the recorded one into `out`.
void compare(const json& recorded, const json& replayed, ReplayedUpdate& out) {
  const std::vector<Vec2> a = ball_positions(recorded), b = ball_positions(replayed);
  out.balls_recorded = static_cast<int>(a.size());
  out.balls_replayed = static_cast<int>(b.size());
  const std::vector<PointPair> pairs = closest_pairs(a, b, kMatchM);
  out.balls_lost = out.balls_recorded - static_cast<int>(pairs.size());
  out.balls_added = out.balls_replayed - static_cast<int>(pairs.size());
  for (const PointPair& p : pairs) {
    out.ball_shift_max_m = std::max(out.ball_shift_max_m, p.distance);
    if (p.distance > kReplayMovedM) ++out.balls_moved;
  }
  const json& r = recorded.at("world").at("robot");
  const json& q = replayed.at("world").at("robot");
  if (!r.is_null() && !q.is_null()) {
    out.robot = "same";
    out.robot_shift_m = std::hypot(r.at("x_m").get<double>() - q.at("x_m").get<double>(),
                                   r.at("y_m").get<double>() - q.at("y_m").get<double>());
    out.robot_turn_deg = std::abs(
        wrap_deg_180(r.at("heading_deg").get<double>() - q.at("heading_deg").get<double>()));
  } else if (!r.is_null() || !q.is_null()) {
    out.robot = r.is_null() ? "added" : "lost";
  }
  out.route_changed = route_changed(recorded.at("route"), replayed.at("route"));
}

}  // namespace

bool ReplayedUpdate::differs() const {
  return balls_added > 0 || balls_lost > 0 || balls_moved > 0 || robot == "added" ||
         robot == "lost" || robot_shift_m > kReplayMovedM || robot_turn_deg > 1.0 || route_changed;
}

UpdateReplayer::UpdateReplayer(UpdatePublisher& publisher, const PlannerOptions& planner,
                               const ReplayOptions& options)
    : publisher_(publisher), planner_(planner), fixed_planner_(options.planner.has_value()) {
  if (options.planner) planner_.kind = *options.planner;
  publisher_.set_planner(planner_);
}

std::uint64_t UpdateReplayer::feed(const RecordedUpdate& recorded, NavigationHub& hub,
                                   std::string& why) {
  why.clear();
  if (recorded.cut_short) {
    why = "the file is cut short in it";
    return 0;
  }
  const std::string kind = recorded.navigation.at("route").at("planner").get<std::string>();
  if (!fixed_planner_ && !kind.empty() && kind != planner_name(planner_.kind)) {
    if (const std::optional<PlannerKind> k = planner_from_name(kind)) {
      planner_.kind = *k;
      publisher_.set_planner(planner_);
    }
  }
  if (recorded.new_frame_set && recorded.frames.any()) {
    const std::uint64_t seq = publisher_.publish(recorded.frames, hub, &recorded.reports);
    world_ = world_ || seq != 0;
    if (seq == 0) why = "the pipeline failed on its frames";
    return seq;
  }
  if (recorded.new_frame_set) {
    why = "its frames were not recorded";
    return 0;
  }
  if (!world_) {
    why = "it re-planned a world the replay has not seen";
    return 0;
  }
  return publisher_.republish(hub, &recorded.reports);
}

ReplayReport replay_run(const RecordedRun& run, const ReplayOptions& options) {
  ReplayReport report{run.path().string(), run.frames(), {}};
  const RunSetup& setup = run.setup();
  UpdatePublisher publisher(setup.site, setup.pipeline, setup.planner);
  UpdateReplayer replayer(publisher, setup.planner, options);
  NavigationHub hub;
  run.for_each_update([&](const RecordedUpdate& recorded) {
    ReplayedUpdate& out = report.updates.emplace_back();
    out.seq = recorded.seq;
    if (const std::uint64_t seq = replayer.feed(recorded, hub, out.not_replayed); seq != 0) {
      compare(recorded.navigation, navigation_json(*hub.find(seq), "", run.camera_names()), out);
    }
    return true;
  });
  return report;
}

json replay_json(const ReplayReport& report, bool all) {
  json per_update = json::array();
  int replayed = 0, differing = 0, added = 0, lost = 0, moved = 0, routes = 0;
  double ball_shift = 0.0, robot_shift = 0.0, robot_turn = 0.0;
  for (const ReplayedUpdate& u : report.updates) {
    if (u.not_replayed.empty()) ++replayed;
    differing += u.differs();
    added += u.balls_added;
    lost += u.balls_lost;
    moved += u.balls_moved;
    routes += u.route_changed;
    ball_shift = std::max(ball_shift, u.ball_shift_max_m);
    robot_shift = std::max(robot_shift, u.robot_shift_m);
    robot_turn = std::max(robot_turn, u.robot_turn_deg);
    if (!all && u.not_replayed.empty() && !u.differs()) continue;
    json entry{{"seq", u.seq}};
    if (!u.not_replayed.empty()) {
      entry["not_replayed"] = u.not_replayed;
    } else {
      entry.update({{"balls_recorded", u.balls_recorded},
                    {"balls_replayed", u.balls_replayed},
                    {"balls_added", u.balls_added},
                    {"balls_lost", u.balls_lost},
                    {"balls_moved", u.balls_moved},
                    {"ball_shift_max_m", u.ball_shift_max_m},
                    {"robot", u.robot},
                    {"robot_shift_m", u.robot_shift_m},
                    {"robot_turn_deg", u.robot_turn_deg},
                    {"route_changed", u.route_changed},
                    {"differs", u.differs()}});
    }
    per_update.push_back(std::move(entry));
  }
  const auto updates = static_cast<int>(report.updates.size());
  return {{"file", report.file},
          {"frames", report.frames},
          {"updates", updates},
          {"replayed", replayed},
          {"not_replayed", updates - replayed},
          {"differing", differing},
          {"balls_added", added},
          {"balls_lost", lost},
          {"balls_moved", moved},
          {"ball_shift_max_m", ball_shift},
          {"robot_shift_max_m", robot_shift},
          {"robot_turn_max_deg", robot_turn},
          {"routes_changed", routes},
          {"per_update", per_update}};
}

}  // namespace ballsight
