#include "ballsight/service/simulated_service.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <opencv2/core/utility.hpp>
#include <thread>
#include <utility>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "ballsight/service/simulated_court.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"

namespace ballsight {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

void SimulatedServiceOptions::validate() const {
  require(std::isfinite(vision_hz) && vision_hz > 0.0 && vision_hz <= 100.0, "--rate",
          "must be in (0, 100] Hz");
  require(std::isfinite(robot_wait_s) && robot_wait_s > 0.0, "robot_wait_s", "must be positive");
  if (balls) {
    require(*balls >= 0 && *balls <= sim::CourtScenarioOptions::kMaxBalls, "--balls",
            "must be in [0, " + std::to_string(sim::CourtScenarioOptions::kMaxBalls) + "]");
  }
  planner.validate();
  robot.validate();
  require(std::isfinite(cluster_share) && cluster_share >= 0.0 && cluster_share <= 1.0,
          "--cluster-share", "must be in [0, 1]");
  require(!resume || !truth_out.empty(), "--resume", "needs --truth-out (the court to resume)");
  for (const CameraOutage& o : camera_outages) {
    require(o.camera >= 0 && o.camera < sim::kCourtRigCameras, "--sim-fail-camera",
            "camera must be 0.." + std::to_string(sim::kCourtRigCameras - 1) +
                " (the court's cameras)");
    require(std::isfinite(o.from_s) && o.from_s >= 0.0, "--sim-fail-camera",
            "time must be a non-negative number of simulated seconds");
    require(o.until_s > o.from_s, "--sim-fail-camera", "the camera must return after it fails");
  }
}

struct SimulatedCourtService::Impl {
  SimulatedServiceOptions options;
  std::unique_ptr<SimulatedCourt> court;
  Site site;  // the court's, with the options' basket
  std::unique_ptr<sim::CourtWorld> world;
  std::unique_ptr<UpdatePublisher> publisher;
  std::atomic<double> render_ms{0.0};

  // The robot's commands (drive()), and what the court did (health()).
  mutable std::mutex mutex;
  std::condition_variable commanded;
  std::uint64_t command_seq = 0;
  sim::DriveCommand command;
  std::optional<Clock::time_point> last_command;
  int unreported = 0;  // balls collected since the robot's last command
  int collected = 0, blocked_ticks = 0, balls_left = 0, held = 0;
  double time_s = 0.0;
  Pose2D robot;
  Pose2D odometry;  // the wheels' (sim::WorldTick::odometry)
  std::vector<bool> camera_failed = std::vector<bool>(sim::kCourtRigCameras, false);  // mutex held
  Pose2D start;  // the robot when this service began
  // The court's record: the scene as it began (written first), or the run this one resumes.
  std::optional<LoopTruth> resumed;
  std::vector<SceneBall> scene_balls;

  std::vector<bool> failed_cameras(double at_s) const {
    std::vector<bool> failed(camera_failed.size(), false);
    for (const CameraOutage& o : options.camera_outages) {
      if (o.covers(at_s)) failed[static_cast<std::size_t>(o.camera)] = true;  // validated
    }
    return failed;
  }

  bool driving(Clock::time_point now) const {  // mutex held
    return last_command && now - *last_command < std::chrono::seconds(3);
  }
};

SimulatedCourtService::SimulatedCourtService(const SimulatedServiceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  Impl& s = *impl_;
  s.options = options;
  s.court = std::make_unique<SimulatedCourt>(
      SimulatedCourtOptions{options.seed, options.balls, options.cluster_share, options.layout,
                            options.obstacles, options.arrange});
  s.site = s.court->site();
  if (options.capacity) s.site.robot.capacity = *options.capacity;
  const Site& site = s.site;
  sim::CourtScene scene = s.court->scene();
  for (const sim::SceneSphere& b : scene.balls) {
    if (b.kind == sim::ObjectKind::tennis_ball) {
      s.scene_balls.push_back({b.id, b.center_in_field.head<2>()});
    }
  }
  if (options.resume && std::filesystem::exists(options.truth_out)) {
    drop_unfinished_line(options.truth_out);
    s.resumed = read_loop_truth(options.truth_out);
    require(s.resumed->seed == options.seed, options.truth_out.string(),
            "records seed " + std::to_string(s.resumed->seed) + ", not --seed " +
                std::to_string(options.seed));
    require(s.resumed->balls.size() == s.scene_balls.size(), options.truth_out.string(),
            "records " + std::to_string(s.resumed->balls.size()) + " balls, not the " +
                std::to_string(s.scene_balls.size()) + " of this scene (--balls)");
  }
  sim::DriveLimits limits;
  limits.max_speed_mps = site.robot.max_speed_mps;
  limits.max_turn_rate_dps = site.robot.turn_rate_dps;
  limits.max_accel_mps2 = site.robot.max_accel_mps2;
  limits.max_turn_accel_dps2 = site.robot.turn_accel_dps2;
  const sim::RobotFootprint footprint =
      sim::RobotFootprint::of(scene.robot, site.robot.collector_x_m, site.robot.collector_width_m);
  sim::RobotImperfections imperfections = options.robot;
  imperfections.seed = options.seed;
  const sim::CollectorBasket basket{site.robot.capacity, site.unload_point(), site.robot.unload_s};
  s.world = std::make_unique<sim::CourtWorld>(std::move(scene), s.court->rig().court, limits,
                                              footprint, imperfections, basket);
  if (s.resumed && !s.resumed->ticks.empty()) {
    std::vector<int> gone;
    for (const TruthTick& t : s.resumed->ticks) {
      gone.insert(gone.end(), t.world.collected.begin(), t.world.collected.end());
      gone.insert(gone.end(), t.removed_by_hand.begin(), t.removed_by_hand.end());
    }
    const TruthTick& last = s.resumed->ticks.back();
    s.world->resume(last.world.time_s, last.world.robot, gone, last.world.held);
    s.held = last.world.held;
    s.collected = static_cast<int>(gone.size());
    s.time_s = last.world.time_s;
    s.camera_failed = s.failed_cameras(s.time_s);  // recorded as they were
  }
  s.balls_left = s.world->balls_left();
  s.start = s.world->motion().pose;
  s.robot = s.world->motion().pose;
  ServicePipeline pipeline{CourtMethod::ballsight, s.court->cameras(), {}};
  if (options.report_pipeline) {
    pipeline.method = CourtMethod::seed;
  } else {
    for (std::size_t c = 0; c < pipeline.cameras.size(); ++c)
      pipeline.empty_court.push_back(s.court->empty_court(c));
  }
  s.publisher = std::make_unique<UpdatePublisher>(site, std::move(pipeline), options.planner);
}

SimulatedCourtService::~SimulatedCourtService() = default;

const Site& SimulatedCourtService::site() const {
  return impl_->site;
}

nlohmann::json SimulatedCourtService::drive(std::uint64_t seq, double speed_mps,
                                            double turn_rate_rps) {
  Impl& s = *impl_;
  nlohmann::json answer;
  {
    const std::lock_guard lock(s.mutex);
    s.command_seq = std::max(s.command_seq, seq);
    s.command = {speed_mps, turn_rate_rps};
    s.last_command = Clock::now();
    answer = {{"collected", s.unreported},
              {"held", s.held},
              {"time_s", s.time_s},
              {"odometry", pose_json(s.odometry)}};
    s.unreported = 0;
  }
  s.commanded.notify_all();
  return answer;
}

void SimulatedCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  Impl& s = *impl_;
  const double period_s = 1.0 / s.options.vision_hz;
  std::ofstream truth;
  const auto record = [&truth](const nlohmann::json& line) {
    if (truth.is_open()) truth << line.dump() << "\n" << std::flush;
  };
  if (!s.options.truth_out.empty()) {
    truth.open(s.options.truth_out, s.resumed ? std::ios::app : std::ios::trunc);
    require(truth.good(), s.options.truth_out.string(), "cannot open for writing");
  }
  if (!s.resumed) record(scene_record(s.options.seed, s.scene_balls, s.world->motion().pose));
  record(event_record(
      {s.world->time_s(), s.resumed ? "service restarted: the court resumed" : "service started"}));
  // A resumed court goes on counting its ticks (fresh sensor noise, not the first run's again).
  std::uint64_t tick = s.resumed ? s.resumed->ticks.size() : 0;
  while (!stop) {
    const auto started = Clock::now();
    bool driving = false;
    {
      const std::lock_guard lock(s.mutex);
      driving = s.options.lockstep || s.driving(started);
    }
    std::vector<int> removed;
    // Each report once: with no robot driving, its ball is taken off by hand.
    const std::vector<Vec2> reported = hub.take_for_hand();
    if (!driving && !reported.empty()) {
      std::vector<Vec2> at;
      std::vector<int> ids;
      for (const sim::SceneSphere& b : s.world->scene().balls) {
        if (b.kind != sim::ObjectKind::tennis_ball) continue;
        at.push_back(b.center_in_field.head<2>());
        ids.push_back(b.id);
      }
      const std::vector<bool> taken = taken_by_reports(at, reported);
      std::vector<int> gone;
      for (std::size_t k = 0; k < ids.size(); ++k) {
        if (taken[k]) gone.push_back(ids[k]);
      }
      removed = s.world->remove_balls_if([&](const sim::SceneSphere& b) {
        return std::find(gone.begin(), gone.end(), b.id) != gone.end();
      });
    }
    // The cameras rendered side by side (the pipeline after them is a few ms).
    std::vector<cv::Mat> frames(s.court->cameras().size());
    const sim::CourtScene& scene = s.world->scene();
    const std::vector<bool> failed = s.failed_cameras(s.world->time_s());
    std::vector<bool> was;
    {
      const std::lock_guard lock(s.mutex);
      was = std::exchange(s.camera_failed, failed);
    }
    for (std::size_t k = 0; k < failed.size(); ++k) {
      if (failed[k] == was[k]) continue;
      record(event_record(
          {s.world->time_s(), s.site.cameras[k].name + (failed[k] ? " failed: no more frames"
                                                                  : " returned: frames again")}));
    }
    cv::parallel_for_(cv::Range(0, static_cast<int>(frames.size())), [&](const cv::Range& r) {
      for (int c = r.start; c < r.end; ++c) {
        const auto k = static_cast<std::size_t>(c);
        if (failed[k]) continue;  // an empty frame: the camera is gone
        frames[k] = s.court->render(k, scene, tick);
      }
    });
    const std::int64_t capture_ns = utc_now_ns();  // the frames exist from now: "captured"
    s.render_ms = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    const std::uint64_t seq =
        s.publisher->publish(frame_set_of(std::move(frames), capture_ns, tick), hub);
    // A driving robot answers this update with its command; the court waits for it.
    sim::DriveCommand command;
    if (s.options.lockstep) {
      std::unique_lock lock(s.mutex);
      // The newest update, not only this one: a report of collected balls publishes one more
      // (the route without them), which the robot answers too before the court goes on.
      while (!stop && hub.acknowledged() < hub.latest_seq()) {
        s.commanded.wait_for(lock, std::chrono::milliseconds(1));
      }
      if (stop) break;  // an update not acknowledged does not move the court
      command = s.command;
    } else {
      std::unique_lock lock(s.mutex);
      if (s.driving(Clock::now())) {
        s.commanded.wait_for(lock, std::chrono::duration<double>(s.options.robot_wait_s),
                             [&] { return s.command_seq >= seq || stop; });
      }
      if (s.driving(Clock::now())) command = s.command;
    }
    const sim::WorldTick& t = s.world->advance(command, period_s);
    {
      const std::lock_guard lock(s.mutex);
      s.unreported += static_cast<int>(t.collected.size());
      s.collected += static_cast<int>(t.collected.size());
      s.blocked_ticks += t.blocked ? 1 : 0;
      s.held = t.held;
      s.balls_left = t.balls_left;
      s.time_s = t.time_s;
      s.robot = t.robot;
      s.odometry = t.odometry;
    }
    if (truth.is_open()) {
      TruthTick line{t, seq, command, {}, std::move(removed)};
      if (const std::optional<NavigationUpdate> u = hub.find(seq)) {
        if (u->world.robot) line.published.robot = u->world.robot->pose;
        line.published.balls_seen = static_cast<int>(u->world.balls.size());
        line.published.waypoints_m = u->route.waypoints_m;
      }
      record(tick_record(line));
    }
    ++tick;
    // Racing ahead is for a robot that drives; a court nobody drives keeps to the wall clock.
    if (s.options.realtime || !driving) {
      std::this_thread::sleep_until(started + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(period_s)));
    }
  }
}

Pose2D SimulatedCourtService::robot_start() const {
  return impl_->start;
}

const std::vector<sim::CourtObstacle>& SimulatedCourtService::scene_obstacles() const {
  return impl_->court->scene().obstacles;
}

const std::vector<SceneBall>& SimulatedCourtService::scene_balls() const {
  return impl_->scene_balls;
}

const std::vector<sim::WorldTick>& SimulatedCourtService::history() const {
  return impl_->world->history();
}

CourtService::SimulatedDrive SimulatedCourtService::simulated_drive() {
  return [this](std::uint64_t seq, double speed_mps, double turn_rate_rps) {
    return drive(seq, speed_mps, turn_rate_rps);
  };
}

UpdatePublisher& SimulatedCourtService::publisher() const {
  return *impl_->publisher;
}

void SimulatedCourtService::republish(NavigationHub& hub) {
  impl_->publisher->republish(hub);
}

nlohmann::json SimulatedCourtService::health() const {
  const Impl& s = *impl_;
  nlohmann::json h = s.publisher->health();
  nlohmann::json cameras = nlohmann::json::array();
  const std::lock_guard lock(s.mutex);
  for (std::size_t k = 0; k < s.site.cameras.size(); ++k) {
    cameras.push_back({{"name", s.site.cameras[k].name},
                       {"state", s.camera_failed[k] ? "failed" : "simulated"},
                       {"frames", h["frame_sets"]}});
  }
  h["cameras"] = cameras;
  h["render_ms"] = s.render_ms.load();
  h["sim"] = {{"time_s", s.time_s},
              {"balls_left", s.balls_left},
              {"collected", s.collected},
              {"held", s.held},
              {"robot", pose_json(s.robot)},
              {"driving", s.driving(Clock::now())},
              {"blocked_ticks", s.blocked_ticks}};
  return h;
}

}  // namespace ballsight
