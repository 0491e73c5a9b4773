#include "ballsight/eval/simulated_service.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/eval/court_eval_calibration.hpp"
#include "ballsight/net/update_planner.hpp"
#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_rig.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

void SimulatedServiceOptions::validate() const {
  require(std::isfinite(max_rate_hz) && max_rate_hz > 0.0 && max_rate_hz <= 1000.0, "rate",
          "must be in (0, 1000] Hz");
  planner.validate();
}

struct SimulatedCourtService::Impl {
  SimulatedServiceOptions options;
  sim::CourtRig rig;
  Site site;
  sim::CourtScene scene;
  std::vector<sim::CourtRenderer> renderers;
  std::unique_ptr<CourtPipeline> pipeline;

  mutable std::mutex mutex;  // guards the figures below
  std::uint64_t frame_sets = 0, published = 0;
  double render_ms = 0.0, pipeline_ms = 0.0, plan_ms = 0.0, rate = 0.0;
  std::string last_error;
};

SimulatedCourtService::SimulatedCourtService(const SimulatedServiceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  Impl& s = *impl_;
  s.options = options;
  s.rig = sim::make_court_rig({}, {}, sim::derive_seed(options.seed, 0));
  s.site = simulated_site(s.rig);
  s.scene = sim::make_court_scene(s.rig.court, {}, sim::derive_seed(options.seed, 1));
  std::vector<FieldCamera> cameras;
  for (const sim::CourtCamera& c : s.rig.cameras) {
    s.renderers.emplace_back(c, s.rig.court);
    cameras.push_back({c.camera, c.camera_from_field});
  }
  s.pipeline = make_ballsight_pipeline(cameras, ballsight_options_for_site(s.site));
}

SimulatedCourtService::~SimulatedCourtService() = default;

const Site& SimulatedCourtService::site() const {
  return impl_->site;
}

std::vector<std::string> SimulatedCourtService::camera_names() const {
  std::vector<std::string> names;
  for (const SiteCamera& c : impl_->site.cameras) names.push_back(c.name);
  return names;
}

void SimulatedCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  Impl& s = *impl_;
  const auto period = std::chrono::duration<double>(1.0 / s.options.max_rate_hz);
  std::optional<Route> previous;
  std::uint64_t tick = 0;
  while (!stop) {
    const auto started = Clock::now();
    // Balls the robot reported collected leave the court.
    const std::vector<Vec2> collected = hub.collected();
    std::erase_if(s.scene.balls, [&](const sim::SceneSphere& b) {
      return b.kind == sim::ObjectKind::tennis_ball &&
             std::any_of(collected.begin(), collected.end(), [&](const Vec2& c) {
               return (c - b.center_in_field.head<2>()).norm() < kCollectedMatchM;
             });
    });
    std::vector<cv::Mat> frames;
    for (std::size_t c = 0; c < s.renderers.size(); ++c) {
      frames.push_back(
          s.renderers[c].render(s.scene, sim::derive_seed(s.options.seed + tick, c + 2)).bgr);
    }
    const std::int64_t capture_ns = utc_now_ns();  // the frames exist from now: "captured"
    const double render_ms = ms_since(started);
    const auto pipeline_started = Clock::now();
    const FrameSetResult result = s.pipeline->process(frames);
    const double pipeline_ms = ms_since(pipeline_started);
    const auto plan_started = Clock::now();
    std::string error;
    NavigationUpdate update;
    try {
      update = plan_update(s.site, result.world, capture_ns, hub, previous ? &*previous : nullptr,
                           s.options.planner);
    } catch (const InputError& e) {  // e.g. a pose the cameras put inside the net
      error = e.what();
      update.capture_time_ns = capture_ns;
      update.world = result.world;
    }
    previous = update.route;
    hub.publish(std::move(update));
    {
      const std::lock_guard lock(s.mutex);
      ++s.frame_sets;
      ++s.published;
      s.render_ms = render_ms;
      s.pipeline_ms = pipeline_ms;
      s.plan_ms = ms_since(plan_started);
      s.last_error = error;
      const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
      s.rate = seconds > 0.0 ? 1.0 / std::max(seconds, period.count()) : 0.0;
    }
    ++tick;
    std::this_thread::sleep_until(started + std::chrono::duration_cast<Clock::duration>(period));
  }
}

nlohmann::json SimulatedCourtService::health() const {
  const Impl& s = *impl_;
  const std::lock_guard lock(s.mutex);
  nlohmann::json cameras = nlohmann::json::array();
  for (const SiteCamera& c : s.site.cameras) {
    cameras.push_back({{"name", c.name}, {"state", "simulated"}, {"frames", s.frame_sets}});
  }
  return {{"cameras", cameras},
          {"frame_sets", s.frame_sets},
          {"updates_published", s.published},
          {"render_ms", s.render_ms},
          {"pipeline_ms", s.pipeline_ms},
          {"plan_ms", s.plan_ms},
          {"frame_sets_per_s", s.rate},
          {"last_error", s.last_error}};
}

}  // namespace ballsight
