#include "ballsight/eval/simulated_service.hpp"

#include <chrono>
#include <cmath>
#include <thread>

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
  std::unique_ptr<UpdatePublisher> publisher;
  std::atomic<double> render_ms{0.0};
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
  s.publisher = std::make_unique<UpdatePublisher>(
      s.site, make_ballsight_pipeline(cameras, ballsight_options_for_site(s.site)),
      options.planner);
}

SimulatedCourtService::~SimulatedCourtService() = default;

const Site& SimulatedCourtService::site() const {
  return impl_->site;
}

void SimulatedCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  Impl& s = *impl_;
  const auto period = std::chrono::duration<double>(1.0 / s.options.max_rate_hz);
  std::uint64_t tick = 0;
  while (!stop) {
    const auto started = Clock::now();
    // Balls the robot reported collected leave the court.
    std::erase_if(s.scene.balls, [&](const sim::SceneSphere& b) {
      return b.kind == sim::ObjectKind::tennis_ball &&
             hub.was_collected(b.center_in_field.head<2>());
    });
    std::vector<cv::Mat> frames;
    for (std::size_t c = 0; c < s.renderers.size(); ++c) {
      frames.push_back(
          s.renderers[c].render(s.scene, sim::derive_seed(s.options.seed + tick, c + 2)).bgr);
    }
    const std::int64_t capture_ns = utc_now_ns();  // the frames exist from now: "captured"
    s.render_ms = std::chrono::duration<double, std::milli>(Clock::now() - started).count();
    s.publisher->publish(frames, capture_ns, hub);
    ++tick;
    std::this_thread::sleep_until(started + std::chrono::duration_cast<Clock::duration>(period));
  }
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
  return h;
}

}  // namespace ballsight
