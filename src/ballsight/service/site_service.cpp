#include "ballsight/service/site_service.hpp"

#include <algorithm>
#include <iostream>
#include <thread>

#include "ballsight/core/enum_names.hpp"
#include "ballsight/pipeline/site_setup.hpp"

namespace ballsight {
namespace {

constexpr EnumNames<CaptureState, 5> kStateNames{{{CaptureState::starting, "starting"},
                                                  {CaptureState::running, "running"},
                                                  {CaptureState::retrying, "retrying"},
                                                  {CaptureState::finished, "finished"},
                                                  {CaptureState::stopped, "stopped"}}};

}  // namespace

SiteCourtService::SiteCourtService(Site site, const SiteServiceOptions& options)
    : site_(std::move(site)), options_(options) {
  publisher_ = std::make_unique<UpdatePublisher>(
      site_, ServicePipeline{CourtMethod::ballsight, site_field_cameras(site_), {}},
      options.planner);
  const auto log = [](const std::string& message) {
    std::cerr << "ballsight serve: " << message << "\n";
  };
  for (const SiteCamera& camera : site_.cameras) {
    captures_.push_back(std::make_unique<CameraCapture>(camera.name, site_frame_source(camera),
                                                        CaptureOptions{}, log));
  }
  figures_.resize(captures_.size());
}

SiteCourtService::~SiteCourtService() = default;

void SiteCourtService::reload_calibration() {
  publisher_->replace_pipeline({CourtMethod::ballsight, site_field_cameras(site_), {}});
}

void SiteCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  std::vector<CameraCapture*> list;
  for (auto& c : captures_) {
    c->start();
    list.push_back(c.get());
  }
  while (!stop) {
    const std::optional<FrameSet> set = next_frame_set(list, options_.wait);
    if (!set || !set->any()) {  // every recorded source has ended, or no camera delivered: the
                                // last update stays
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      continue;
    }
    {
      const std::lock_guard lock(mutex_);
      for (const CameraFrame& f : set->cameras) {
        if (f.image.empty()) continue;
        CameraFigures& fig = figures_[f.camera];
        if (fig.last_frame && f.received > *fig.last_frame) {
          const double hz =
              1.0 / std::chrono::duration<double>(f.received - *fig.last_frame).count();
          fig.rate_hz = smoothed_rate(fig.rate_hz, hz);
        }
        fig.last_frame = f.received;
      }
    }
    publisher_->publish(*set, hub);
  }
  for (auto& c : captures_) c->stop();
}

void SiteCourtService::republish(NavigationHub& hub) {
  publisher_->republish(hub);
}

nlohmann::json SiteCourtService::health() const {
  nlohmann::json cameras = nlohmann::json::array();
  const auto now = CaptureClock::now();
  {
    const std::lock_guard lock(mutex_);
    for (std::size_t c = 0; c < captures_.size(); ++c) {
      const CaptureStatus s = captures_[c]->status();
      const CameraFigures& fig = figures_[c];
      cameras.push_back(
          {{"name", captures_[c]->name()},
           {"state", enum_name(kStateNames, s.state)},
           {"frames", s.frames},
           {"frames_per_s", fig.rate_hz},
           {"last_frame_age_s",
            fig.last_frame
                ? nlohmann::json(std::chrono::duration<double>(now - *fig.last_frame).count())
                : nlohmann::json(nullptr)},
           {"failures", s.failures_total},
           {"last_error", s.last_error}});
    }
  }
  nlohmann::json h = publisher_->health();
  h["cameras"] = cameras;
  return h;
}

}  // namespace ballsight
