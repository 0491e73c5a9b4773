#include "ballsight/eval/simulated_service.hpp"

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <thread>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/eval/court_eval_calibration.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/seeding.hpp"

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
}

struct SimulatedCourtService::Impl {
  SimulatedServiceOptions options;
  sim::CourtRig rig;
  Site site;
  std::unique_ptr<sim::CourtWorld> world;
  std::vector<sim::CourtRenderer> renderers;
  std::unique_ptr<UpdatePublisher> publisher;
  std::atomic<double> render_ms{0.0};

  // The robot's commands (drive()), and what the court did (health()).
  mutable std::mutex mutex;
  std::condition_variable commanded;
  std::uint64_t command_seq = 0;
  sim::DriveCommand command;
  std::optional<Clock::time_point> last_command;
  int unreported = 0;  // balls collected since the robot's last command
  int collected = 0, blocked_ticks = 0, balls_left = 0;
  double time_s = 0.0;
  Pose2D robot;

  bool driving(Clock::time_point now) const {  // mutex held
    return last_command && now - *last_command < std::chrono::seconds(3);
  }
};

SimulatedCourtService::SimulatedCourtService(const SimulatedServiceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  Impl& s = *impl_;
  s.options = options;
  s.rig = sim::make_court_rig({}, {}, sim::derive_seed(options.seed, 0));
  s.site = simulated_site(s.rig);
  sim::CourtScenarioOptions scenario;
  scenario.ball_count = options.balls;
  sim::CourtScene scene =
      sim::make_court_scene(s.rig.court, scenario, sim::derive_seed(options.seed, 1));
  sim::DriveLimits limits;
  limits.max_speed_mps = s.site.robot.max_speed_mps;
  limits.max_turn_rate_dps = s.site.robot.turn_rate_dps;
  limits.max_accel_mps2 = s.site.robot.max_accel_mps2;
  limits.max_turn_accel_dps2 = s.site.robot.turn_accel_dps2;
  const sim::RobotFootprint footprint = sim::RobotFootprint::of(
      scene.robot, s.site.robot.collector_x_m, s.site.robot.collector_width_m);
  s.world = std::make_unique<sim::CourtWorld>(std::move(scene), s.rig.court, limits, footprint);
  s.balls_left = s.world->balls_left();
  s.robot = s.world->motion().pose;
  std::vector<FieldCamera> cameras;
  for (const sim::CourtCamera& c : s.rig.cameras) {
    s.renderers.emplace_back(c, s.rig.court);
    cameras.push_back({c.camera, c.camera_from_field});
  }
  s.publisher = std::make_unique<UpdatePublisher>(
      s.site,
      options.report_pipeline
          ? make_seed_pipeline(std::move(cameras), seed_options_for_site(s.site))
          : make_ballsight_pipeline(std::move(cameras), ballsight_options_for_site(s.site)),
      options.planner);
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
    answer = {{"collected", s.unreported}, {"time_s", s.time_s}};
    s.unreported = 0;
  }
  s.commanded.notify_all();
  return answer;
}

void SimulatedCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  Impl& s = *impl_;
  const double period_s = 1.0 / s.options.vision_hz;
  std::ofstream truth;
  if (!s.options.truth_out.empty()) {
    truth.open(s.options.truth_out);
    require(truth.good(), s.options.truth_out.string(), "cannot open for writing");
  }
  std::uint64_t tick = 0;
  while (!stop) {
    const auto started = Clock::now();
    bool driving = false;
    {
      const std::lock_guard lock(s.mutex);
      driving = s.driving(started);
    }
    if (!driving) {  // no robot drives: balls reported collected are taken off by hand
      s.world->remove_balls_if([&](const sim::SceneSphere& b) {
        return hub.was_collected(b.center_in_field.head<2>());
      });
    }
    std::vector<cv::Mat> frames;
    for (std::size_t c = 0; c < s.renderers.size(); ++c) {
      frames.push_back(s.renderers[c]
                           .render(s.world->scene(), sim::derive_seed(s.options.seed + tick, c + 2))
                           .bgr);
    }
    const std::int64_t capture_ns = utc_now_ns();  // the frames exist from now: "captured"
    s.render_ms = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    const std::uint64_t seq = s.publisher->publish(frames, capture_ns, hub);
    // A driving robot answers this update with its command; the court waits for it.
    sim::DriveCommand command;
    {
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
      s.balls_left = t.balls_left;
      s.time_s = t.time_s;
      s.robot = t.robot;
    }
    if (truth.is_open()) {
      truth << nlohmann::json{{"time_s", t.time_s},
                              {"seq", seq},
                              {"robot",
                               {{"x_m", t.robot.position.x()},
                                {"y_m", t.robot.position.y()},
                                {"heading_deg", deg_from_rad(t.robot.heading_rad)}}},
                              {"command",
                               {{"speed_mps", command.speed_mps},
                                {"turn_rate_dps", deg_from_rad(command.turn_rate_rps)}}},
                              {"collected", t.collected},
                              {"balls_left", t.balls_left},
                              {"blocked", t.blocked}}
                   .dump()
            << "\n"
            << std::flush;
    }
    ++tick;
    // Racing ahead is for a robot that drives; a court nobody drives keeps to the wall clock.
    if (s.options.realtime || !driving) {
      std::this_thread::sleep_until(started + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(period_s)));
    }
  }
}

const std::vector<sim::WorldTick>& SimulatedCourtService::history() const {
  return impl_->world->history();
}

ApiContext SimulatedCourtService::api_context(NavigationHub& hub) {
  ApiContext context = CourtService::api_context(hub);
  context.drive = [this](std::uint64_t seq, double speed_mps, double turn_rate_rps) {
    return drive(seq, speed_mps, turn_rate_rps);
  };
  return context;
}

void SimulatedCourtService::republish(NavigationHub& hub) {
  impl_->publisher->republish(hub);
}

nlohmann::json SimulatedCourtService::health() const {
  const Impl& s = *impl_;
  nlohmann::json h = s.publisher->health();
  nlohmann::json cameras = nlohmann::json::array();
  for (const SiteCamera& c : s.site.cameras) {
    cameras.push_back({{"name", c.name}, {"state", "simulated"}, {"frames", h["frame_sets"]}});
  }
  h["cameras"] = cameras;
  h["render_ms"] = s.render_ms.load();
  const std::lock_guard lock(s.mutex);
  h["sim"] = {{"time_s", s.time_s},
              {"balls_left", s.balls_left},
              {"collected", s.collected},
              {"robot",
               {{"x_m", s.robot.position.x()},
                {"y_m", s.robot.position.y()},
                {"heading_deg", deg_from_rad(s.robot.heading_rad)}}},
              {"driving", s.driving(Clock::now())},
              {"blocked_ticks", s.blocked_ticks}};
  return h;
}

}  // namespace ballsight
