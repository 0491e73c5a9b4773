#include "ballsight/eval/loop_eval.hpp"

#include <cmath>
#include <map>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/eval/wall_clock.hpp"
#include "ballsight/robot/collector_robot.hpp"
#include "ballsight/service/loop_truth.hpp"

namespace ballsight::eval {

const std::vector<LoopSystem>& loop_systems() {
  static const std::vector<LoopSystem> kSystems{
      {"report", true, PlannerKind::priority},
      {"priority", false, PlannerKind::priority},
      {"ballsight", false, PlannerKind::ballsight},
  };
  return kSystems;
}

std::string LoopLayout::name() const {
  if (clustered) return "clustered";
  return others == sim::BallLayout::scattered ? "uniform" : std::string(ball_layout_name(others));
}

const std::vector<LoopLayout>& loop_layouts() {
  static const std::vector<LoopLayout> kLayouts{{false, sim::BallLayout::scattered},
                                                {true, sim::BallLayout::scattered},
                                                {false, sim::BallLayout::along_net},
                                                {false, sim::BallLayout::along_fence},
                                                {false, sim::BallLayout::net_posts}};
  return kLayouts;
}

sim::ObstacleOptions loop_obstacles(int k) {
  sim::ObstacleOptions o;
  if (k % 3 == 1) o.people = o.bags = 1;
  if (k % 3 == 2) o.walkers = 1;
  return o;
}

std::string obstacles_name(const std::vector<sim::CourtObstacle>& obstacles) {
  std::string name;
  for (const sim::CourtObstacle& o : obstacles) {
    name += name.empty() ? "" : "+";
    name += o.walk_to ? "walker" : std::string(sim::obstacle_kind_name(o.kind));
  }
  return name.empty() ? "none" : name;
}

LoopRun run_loop(const LoopSystem& system, const LoopScene& scene, double max_time_s,
                 const RobotConnector& connect, const std::filesystem::path& record,
                 const LoopRobot& robot, const RecordOptions* mcap) {
  SimulatedServiceOptions options;
  options.truth_out = record;
  options.seed = scene.seed;
  options.balls = scene.balls;
  options.cluster_share = scene.layout.clustered ? 0.75 : 0.0;
  options.layout = scene.layout.others;
  options.obstacles = scene.obstacles;
  options.arrange = scene.arrange;
  options.report_pipeline = system.report_pipeline;
  options.planner.kind = system.planner;
  options.lockstep = true;
  options.robot = robot.body;
  options.capacity = robot.capacity;
  SimulatedCourtService service(options);
  NavigationHub hub;
  const std::unique_ptr<RobotLink> link = connect(service, hub);
  std::optional<RunRecorder> recorder;
  if (mcap) recorder.emplace(hub, service, *mcap);
  const Pose2D start = service.robot_start();
  std::atomic<bool> stop{false};
  std::thread court([&] { service.run(hub, stop); });
  std::atomic<bool> robot_done{false};
  CollectorOptions collector;
  collector.latency_s = robot.steer_ahead_s;
  CollectorResult driven;
  std::thread driver([&] {
    driven = run_collector(*link, collector, stop);
    robot_done = true;
  });
  // Until the court is empty, out of time (simulated), or the robot sees no ball left.
  while (!robot_done) {
    const nlohmann::json sim = service.health()["sim"];
    if (sim["balls_left"] == 0 || sim["time_s"].get<double>() >= max_time_s) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  stop = true;
  driver.join();
  court.join();
  link->stop();
  if (recorder) recorder->finish();

  // The court is stopped from here, at wall-clock moments: a run is scored on its first
  // max_time_s simulated seconds, the same ticks every time.
  std::vector<sim::WorldTick> ticks = service.history();
  std::erase_if(ticks, [&](const sim::WorldTick& t) { return t.time_s > max_time_s + 1e-6; });
  const sim::RobotFootprint footprint = collector_footprint(service.site().robot);
  const LoopScore score = score_loop(scene.balls, start, ticks, footprint);
  LoopRun run;
  run.system = system.name;
  run.seed = scene.seed;
  run.layout = scene.layout.name();
  run.obstacles = obstacles_name(service.scene_obstacles());
  run.balls = score.balls;
  const sim::TennisCourtSpec spec;  // the referee's court, as score_loop's
  std::vector<sim::CourtObstacle> standing = service.scene_obstacles();
  std::erase_if(standing, [](const sim::CourtObstacle& o) { return o.walk_to.has_value(); });
  for (const SceneBall& b : service.scene_balls()) {
    run.reachable +=
        sim::mouth_can_reach(footprint, b.position_m, service.site().ball_radius_m, spec, standing)
            ? 1
            : 0;
  }
  run.collected = score.collected;
  run.unreachable = driven.unreachable;
  run.time_s = score.all ? score.time_s : max_time_s;
  run.distance_m = score.distance_m;
  run.all = score.all;
  run.timed_out = !score.all && !driven.done;
  run.never_overlapped = score.never_overlapped;
  run.stalls = driven.stalls;
  run.recoveries = driven.recoveries;
  run.contacts = score.blocked_ticks;
  run.dead_reckoned = driven.dead_reckoned;
  run.guarded = driven.guarded;
  run.min_clearance_m = score.min_clearance_m;
  run.unloads = score.unloads;
  return run;
}

void LoopEvalOptions::validate() const {
  require(scenes >= 1 && scenes <= 100, "--scenes", "must be in [1, 100]");
  require(min_balls >= 1 && min_balls <= max_balls && max_balls <= 200, "balls",
          "need 1 <= min <= max <= 200");
  require(std::isfinite(max_time_s) && max_time_s > 0.0, "--max-time", "must be positive");
  require(!record_mcap || !record_dir.empty(), "--record-mcap", "needs --record-dir");
  robot.body.validate();
  require(!robot.capacity || (*robot.capacity >= 1 && *robot.capacity <= 1000), "--capacity",
          "must be 1 to 1000 balls");
  require(std::isfinite(robot.steer_ahead_s) && robot.steer_ahead_s >= 0.0 &&
              robot.steer_ahead_s <= 5.0,
          "steer_ahead_s", "must be in [0, 5] s");
  for (const std::string& name : systems) {
    require(std::any_of(loop_systems().begin(), loop_systems().end(),
                        [&](const LoopSystem& s) { return s.name == name; }),
            "--systems", "unknown system '" + name + "' (report, priority, ballsight)");
  }
  for (const std::string& name : layouts) {
    require(
        std::any_of(loop_layouts().begin(), loop_layouts().end(),
                    [&](const LoopLayout& l) { return l.name() == name; }),
        "--layouts",
        "unknown layout '" + name + "' (uniform, clustered, along_net, along_fence, net_posts)");
  }
}

std::vector<LoopRun> run_loop_eval(const LoopEvalOptions& options, const RobotConnector& connect,
                                   const std::function<void(const LoopRun&)>& progress) {
  options.validate();
  std::vector<LoopLayout> layouts;
  for (const LoopLayout& layout : loop_layouts()) {
    if (options.layouts.empty() || std::find(options.layouts.begin(), options.layouts.end(),
                                             layout.name()) != options.layouts.end()) {
      layouts.push_back(layout);
    }
  }
  std::vector<LoopRun> runs;
  for (int k = 0; k < options.scenes; ++k) {
    const int balls = options.scenes == 1
                          ? options.min_balls
                          : options.min_balls +
                                (options.max_balls - options.min_balls) * k / (options.scenes - 1);
    for (const LoopSystem& system : loop_systems()) {
      if (!options.systems.empty() && std::find(options.systems.begin(), options.systems.end(),
                                                system.name) == options.systems.end()) {
        continue;
      }
      const LoopScene scene{options.seed + static_cast<std::uint64_t>(k),
                            balls,
                            layouts[static_cast<std::size_t>(k) % layouts.size()],
                            options.obstacles ? *options.obstacles : loop_obstacles(k),
                            {}};
      const std::filesystem::path record =
          options.record_dir.empty()
              ? std::filesystem::path()
              : options.record_dir / (system.name + "-" + std::to_string(scene.seed) + ".jsonl");
      if (!record.empty()) ensure_directory(options.record_dir);
      std::optional<RecordOptions> mcap;
      if (options.record_mcap && !record.empty()) {
        mcap.emplace();
        mcap->path = std::filesystem::path(record).replace_extension(".mcap");
        mcap->frame_every = 10;
        mcap->wait_for_room = true;  // simulated time: the court waits, nothing is dropped
      }
      runs.push_back(run_loop(system, scene, options.max_time_s, connect, record, options.robot,
                              mcap ? &*mcap : nullptr));
      if (progress) progress(runs.back());
    }
  }
  return runs;
}

nlohmann::json loop_eval_json(const std::vector<LoopRun>& runs) {
  std::map<std::string, std::vector<const LoopRun*>> by_system;
  for (const LoopRun& r : runs) by_system[r.system].push_back(&r);
  const auto mean_time = [&](const std::string& name) {
    double sum = 0.0;
    for (const LoopRun* r : by_system[name]) sum += r->time_s;
    return by_system[name].empty() ? 0.0 : sum / static_cast<double>(by_system[name].size());
  };
  nlohmann::json systems = nlohmann::json::object();
  for (const auto& [name, list] : by_system) {
    int balls = 0, collected = 0;
    double distance = 0.0;
    nlohmann::json rows = nlohmann::json::array();
    for (const LoopRun* r : list) {
      balls += r->balls;
      collected += r->collected;
      distance += r->distance_m;
      rows.push_back({{"seed", r->seed},
                      {"layout", r->layout},
                      {"balls", r->balls},
                      {"collected", r->collected},
                      {"all", r->all},
                      {"time_s", r->time_s},
                      {"distance_m", r->distance_m},
                      {"never_overlapped", r->never_overlapped},
                      {"stalls", r->stalls},
                      {"contacts", r->contacts},
                      {"dead_reckoned", r->dead_reckoned},
                      {"guarded", r->guarded},
                      {"min_clearance_m", r->min_clearance_m},
                      {"unloads", r->unloads}});
    }
    const double n = static_cast<double>(list.size());
    nlohmann::json s{
        {"collected_fraction", balls > 0 ? static_cast<double>(collected) / balls : 0.0},
        {"time_s_mean", mean_time(name)},
        {"distance_m_mean", distance / n},
        {"runs", rows}};
    if (by_system.count("ballsight") && mean_time("ballsight") > 0.0) {
      s["time_ratio_to_ballsight"] = mean_time(name) / mean_time("ballsight");
    }
    systems[name] = s;
  }
  // Scene by scene, in the order run (each scene's systems one after the other).
  nlohmann::json scenes = nlohmann::json::array();
  for (const LoopRun& r : runs) {
    if (scenes.empty() || scenes.back()["seed"] != r.seed) {
      scenes.push_back({{"seed", r.seed},
                        {"layout", r.layout},
                        {"obstacles", r.obstacles},
                        {"balls", r.balls},
                        {"reachable", r.reachable},
                        {"systems", nlohmann::json::object()}});
    }
    scenes.back()["systems"][r.system] = {
        {"collected", r.collected},   {"unreachable", r.unreachable},
        {"time_s", r.time_s},         {"timed_out", r.timed_out},
        {"contacts", r.contacts},     {"stalls", r.stalls},
        {"recoveries", r.recoveries}, {"min_clearance_m", r.min_clearance_m},
        {"unloads", r.unloads}};
  }
  // Every figure is simulated (time_s is the court's clock): nothing to keep apart.
  return with_wall_clock_apart({{"systems", systems}, {"scenes", scenes}}, {});
}

}  // namespace ballsight::eval
