#include "ballsight/service/court_service.hpp"

#include "ballsight/core/error.hpp"
#include "ballsight/service/update_planner.hpp"

namespace ballsight {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

double smoothed_rate(double previous_hz, double sample_hz) {
  return previous_hz == 0.0 ? sample_hz : 0.8 * previous_hz + 0.2 * sample_hz;
}

std::vector<std::string> CourtService::camera_names() const {
  std::vector<std::string> names;
  for (const SiteCamera& c : site().cameras) names.push_back(c.name);
  return names;
}

PlannerKind CourtService::planner() const {
  return publisher().planner().kind;
}

void CourtService::set_planner(PlannerKind kind, NavigationHub& hub) {
  PlannerOptions options = publisher().planner();
  options.kind = kind;
  publisher().set_planner(options);
  republish(hub);
}

PlannerOptions CourtService::planner_options() const {
  return publisher().planner();
}

std::vector<FieldCamera> CourtService::cameras() const {
  return publisher().cameras();
}

ServicePipeline CourtService::pipeline_setup() const {
  return publisher().pipeline_setup();
}

std::uint64_t CourtService::pipeline_generation() const {
  return publisher().pipeline_generation();
}

std::optional<CameraView> CourtService::camera_view(std::size_t index) const {
  return publisher().camera_view(index);
}

UpdatePublisher::UpdatePublisher(const Site& site, ServicePipeline pipeline,
                                 const PlannerOptions& planner)
    : site_(site),
      setup_(std::move(pipeline)),
      pipeline_(make_service_pipeline(site_, setup_)),
      planner_(planner),
      views_(pipeline_->cameras().size()),
      next_planner_(planner) {
  planner_.validate();
}

std::vector<FieldCamera> UpdatePublisher::cameras() const {
  const std::lock_guard lock(pipeline_mutex_);
  return pipeline_->cameras();
}

ServicePipeline UpdatePublisher::pipeline_setup() const {
  const std::lock_guard lock(pipeline_mutex_);
  return setup_;
}

void UpdatePublisher::replace_pipeline(ServicePipeline pipeline) {
  std::unique_ptr<CourtPipeline> made = make_service_pipeline(site_, pipeline);
  const std::lock_guard lock(pipeline_mutex_);
  require(made->cameras().size() == pipeline_->cameras().size(), "pipeline",
          "is for another number of cameras");
  setup_ = std::move(pipeline);
  pipeline_ = std::move(made);
  ++generation_;
}

std::uint64_t UpdatePublisher::publish(const FrameSet& frames, NavigationHub& hub,
                                       const ClientReports* reports) {
  return publish_result(frames, hub, reports,
                        [&](CourtPipeline& pipeline) { return pipeline.process(frames); });
}

std::uint64_t UpdatePublisher::publish_detections(const CameraDetectionLists& detections,
                                                  std::int64_t capture_ns, NavigationHub& hub) {
  return publish_result({}, hub, nullptr, [&](CourtPipeline& pipeline) {
    FrameSetResult result;
    result.detections = detections;
    result.camera_errors.resize(detections.size());
    result.world = pipeline.fuse(detections);
    result.world.capture_time_ns = capture_ns;
    return result;
  });
}

std::uint64_t UpdatePublisher::publish_result(
    const FrameSet& frames, NavigationHub& hub, const ClientReports* reports,
    const std::function<FrameSetResult(CourtPipeline&)>& run) {
  const auto started = Clock::now();
  FrameSetResult result;
  try {
    const std::lock_guard pipeline_lock(pipeline_mutex_);
    result = run(*pipeline_);
  } catch (const std::exception& e) {  // a bad frame must not end the service: say so, go on
    const std::lock_guard lock(mutex_);
    ++failed_;
    last_error_ = std::string("pipeline: ") + e.what();
    return 0;
  }
  const double pipeline_ms = ms_since(started);
  std::vector<CameraView> views(frames.cameras.size());
  for (std::size_t k = 0; k < views.size(); ++k) {
    views[k].frame = frames.cameras[k].image;
    views[k].capture_ns = frames.cameras[k].capture_time_ns;
    if (k < result.detections.size() && result.detections[k]) {
      views[k].detections = std::move(*result.detections[k]);  // not needed past the world model
    }
  }
  const std::lock_guard plan_lock(plan_mutex_);
  // Under the plan lock: a re-plan of the old world never runs without the reports it needs.
  hub.frames_fused(result.world.capture_time_ns);
  last_world_ = std::move(result.world);
  const auto plan_started = Clock::now();
  // The views and the health's figures are there before anyone hears of the update (a client
  // that asks for the health once it has the update finds its frame set counted).
  return plan_and_publish(hub, reports, [&](std::uint64_t published_seq) {
    const double plan_ms = ms_since(plan_started);
    const std::lock_guard lock(mutex_);
    for (std::size_t k = 0; k < views.size() && k < views_.size(); ++k) {
      if (views[k].frame.empty()) continue;  // a missing frame: the camera's last view stays
      views[k].seq = published_seq;
      views_[k] = std::move(views[k]);
    }
    ++frame_sets_;
    pipeline_ms_ = pipeline_ms;
    plan_ms_ = plan_ms;
    const auto now = Clock::now();
    if (last_) {
      const double hz = 1.0 / std::max(1e-6, std::chrono::duration<double>(now - *last_).count());
      rate_hz_ = smoothed_rate(rate_hz_, hz);
    }
    last_ = now;
  });
}

std::uint64_t UpdatePublisher::republish(NavigationHub& hub, const ClientReports* reports) {
  const std::lock_guard plan_lock(plan_mutex_);
  if (!last_world_) return 0;  // nothing seen yet
  return plan_and_publish(hub, reports);
}

std::uint64_t UpdatePublisher::plan_and_publish(
    NavigationHub& hub, const ClientReports* reports,
    const std::function<void(std::uint64_t)>& published) {
  std::string error;
  NavigationUpdate update =
      publishable_update(site_, *last_world_, reports ? *reports : hub.reports(),
                         previous_ ? &*previous_ : nullptr, planner_, error);
  previous_ = update.route;
  const std::uint64_t seq = hub.publish(std::move(update), published);
  const std::lock_guard lock(mutex_);
  last_error_ = error;
  return seq;
}

void UpdatePublisher::set_planner(const PlannerOptions& planner) {
  planner.validate();
  {
    const std::lock_guard lock(mutex_);
    next_planner_ = planner;
  }
  const std::lock_guard plan_lock(plan_mutex_);
  // Another planner starts afresh, not from the other one's route; the same one goes on.
  if (planner.kind != planner_.kind) previous_.reset();
  planner_ = planner;
}

PlannerOptions UpdatePublisher::planner() const {
  const std::lock_guard lock(mutex_);
  return next_planner_;
}

std::optional<CameraView> UpdatePublisher::camera_view(std::size_t index) const {
  const std::lock_guard lock(mutex_);
  return index < views_.size() ? views_[index] : std::nullopt;
}

nlohmann::json UpdatePublisher::health() const {
  const std::lock_guard lock(mutex_);
  return {{"frame_sets", frame_sets_},    {"pipeline_ms", pipeline_ms_},
          {"plan_ms", plan_ms_},          {"frame_sets_per_s", rate_hz_},
          {"frame_sets_failed", failed_}, {"last_error", last_error_}};
}

}  // namespace ballsight
