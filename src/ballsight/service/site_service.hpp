#pragma once
// `ballsight serve --site SITE.yml`: the site's cameras captured in parallel (the capture of
// `court run`: a thread per camera, reopened with back-off when it fails), every frame set
// through ballsight's court pipeline, planned and published.

#include <memory>

#include "ballsight/pipeline/capture.hpp"
#include "ballsight/service/court_service.hpp"

namespace ballsight {

struct SiteServiceOptions {
  PlannerOptions planner;
  std::chrono::milliseconds wait{2000};  // for a frame of every live camera, at most
};

class SiteCourtService : public CourtService {
 public:
  /// Throws InputError naming what is wrong in the site's cameras.
  SiteCourtService(Site site, const SiteServiceOptions& options);
  ~SiteCourtService() override;

  const Site& site() const override { return site_; }
  void run(NavigationHub& hub, const std::atomic<bool>& stop) override;
  void republish(NavigationHub& hub) override;
  /// Per camera: "state" (starting, running, retrying, finished, stopped), "frames",
  /// "frames_per_s", "last_frame_age_s" (null before the first), "failures", "last_error".
  nlohmann::json health() const override;
  void reload_calibration() override;

 protected:
  UpdatePublisher& publisher() const override { return *publisher_; }

 private:
  struct CameraFigures {
    double rate_hz = 0.0;
    std::optional<CaptureClock::time_point> last_frame;  // received
  };

  Site site_;
  SiteServiceOptions options_;
  std::vector<std::unique_ptr<CameraCapture>> captures_;
  std::unique_ptr<UpdatePublisher> publisher_;
  mutable std::mutex mutex_;  // guards figures_
  std::vector<CameraFigures> figures_;
};

}  // namespace ballsight
