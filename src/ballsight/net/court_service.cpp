#include "ballsight/net/court_service.hpp"

#include "ballsight/core/error.hpp"
#include "ballsight/net/update_planner.hpp"

namespace ballsight {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

std::vector<std::string> CourtService::camera_names() const {
  std::vector<std::string> names;
  for (const SiteCamera& c : site().cameras) names.push_back(c.name);
  return names;
}

UpdatePublisher::UpdatePublisher(const Site& site, std::unique_ptr<CourtPipeline> pipeline,
                                 const PlannerOptions& planner)
    : site_(site), pipeline_(std::move(pipeline)), planner_(planner) {
  planner_.validate();
}

FrameSetResult UpdatePublisher::publish(const std::vector<cv::Mat>& frames, std::int64_t capture_ns,
                                        NavigationHub& hub) {
  const auto started = Clock::now();
  FrameSetResult result = pipeline_->process(frames);
  const double pipeline_ms = ms_since(started);
  const auto plan_started = Clock::now();
  std::string error;
  NavigationUpdate update;
  try {
    update = plan_update(site_, result.world, capture_ns, hub, previous_ ? &*previous_ : nullptr,
                         planner_);
  } catch (const InputError& e) {  // e.g. a pose the cameras put inside the net
    error = e.what();
    update.capture_time_ns = capture_ns;
    update.world = result.world;
  }
  const double plan_ms = ms_since(plan_started);
  previous_ = update.route;
  hub.publish(std::move(update));
  const std::lock_guard lock(mutex_);
  ++frame_sets_;
  pipeline_ms_ = pipeline_ms;
  plan_ms_ = plan_ms;
  last_error_ = error;
  const auto now = Clock::now();
  if (last_) {
    const double hz = 1.0 / std::max(1e-6, std::chrono::duration<double>(now - *last_).count());
    rate_hz_ = rate_hz_ == 0.0 ? hz : 0.8 * rate_hz_ + 0.2 * hz;
  }
  last_ = now;
  return result;
}

nlohmann::json UpdatePublisher::health() const {
  const std::lock_guard lock(mutex_);
  return {{"frame_sets", frame_sets_},
          {"pipeline_ms", pipeline_ms_},
          {"plan_ms", plan_ms_},
          {"frame_sets_per_s", rate_hz_},
          {"last_error", last_error_}};
}

}  // namespace ballsight
