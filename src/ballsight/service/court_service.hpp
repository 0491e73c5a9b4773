#pragma once
// What `ballsight serve` serves, without any transport: a court service turns frame sets into
// navigation updates and publishes them into the hub, on a thread of its own (a transport only
// hears the sequence number). Three kinds: the site's cameras (site_service.hpp), the simulated
// court (simulated_service.hpp) and a court fed by camera nodes over DDS
// (dds/court_node.hpp). All take the same step for every frame set: UpdatePublisher. The
// transports are adapters over this: API v1 over HTTP (net/service_api.hpp) and ROS 2 topics
// (dds/court_topics.hpp).

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/pipeline/court_pipeline.hpp"
#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/service/camera_view.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

class UpdatePublisher;

class CourtService {
 public:
  virtual ~CourtService() = default;
  virtual const Site& site() const = 0;
  /// Captures, plans and publishes into `hub` until `stop` is set.
  virtual void run(NavigationHub& hub, const std::atomic<bool>& stop) = 0;
  /// Plans the last world model again and publishes it (balls were reported collected: they
  /// leave the plan at once, not at the next frame set). Any thread.
  virtual void republish(NavigationHub& hub) = 0;
  /// {"cameras": [{"name", "state", "frames", ...}], figures of UpdatePublisher::health()}.
  virtual nlohmann::json health() const = 0;

  std::vector<std::string> camera_names() const;

  /// The planner of the next plans.
  PlannerKind planner() const;
  /// All of the next plans' options.
  PlannerOptions planner_options() const;
  /// Plans with `kind` from now on, and plans the last world model again with it into `hub`.
  void set_planner(PlannerKind kind, NavigationHub& hub);

  /// The simulated robot's command for update `seq` (speed m/s, turn rate rad/s): it drives the
  /// next vision period; answers {"collected", "time_s"}. Only a simulated court has a robot to
  /// drive: empty elsewhere.
  using SimulatedDrive =
      std::function<nlohmann::json(std::uint64_t seq, double speed_mps, double turn_rate_rps)>;
  virtual SimulatedDrive simulated_drive() { return {}; }

  /// Every camera as the pipeline uses it (intrinsics and pose), in site order.
  std::vector<FieldCamera> cameras() const;
  /// What its pipeline is made of (a recording keeps it, to replay the run), and how many times
  /// it was replaced (UpdatePublisher::pipeline_generation).
  ServicePipeline pipeline_setup() const;
  std::uint64_t pipeline_generation() const;
  /// Camera `index`'s last frame through the pipeline; nullopt before its first. Any thread.
  std::optional<CameraView> camera_view(std::size_t index) const;
  /// Reads the cameras' calibration files again and runs the pipeline on them from the next
  /// frame set (a camera re-calibrated while the service runs). Throws InputError naming the file
  /// at fault; the pipeline stays as it was then. The simulated court has no files: a no-op.
  virtual void reload_calibration() {}

 protected:
  virtual UpdatePublisher& publisher() const = 0;
};

/// A rate (frames or frame sets per second) smoothed over the last few samples; 0: none yet.
double smoothed_rate(double previous_hz, double sample_hz);

/// One frame set through the court pipeline, planned (warm-started from the previous route) and
/// published. Thread-safe.
class UpdatePublisher {
 public:
  /// Runs make_service_pipeline(site, pipeline). Throws InputError naming what is wrong.
  UpdatePublisher(const Site& site, ServicePipeline pipeline, const PlannerOptions& planner);

  /// One frame set -> one update (with the set's capture time); its seq. Reports of collected
  /// balls the frames confirm are forgotten. A pipeline failure publishes nothing (0) and is
  /// counted (health). The plan weighs the hub's reports, or `reports` when given (a replay: the
  /// reports the recorded update was planned with).
  std::uint64_t publish(const FrameSet& frames, NavigationHub& hub,
                        const ClientReports* reports = nullptr);
  /// The same from detections made elsewhere (camera nodes): one list per camera in camera
  /// order, nullopt for a camera without a usable frame; only the pipeline's fusion runs here.
  std::uint64_t publish_detections(const CameraDetectionLists& detections, std::int64_t capture_ns,
                                   NavigationHub& hub);
  /// The last world model planned again and published: its seq; nothing (0) before the first
  /// frame set.
  std::uint64_t republish(NavigationHub& hub, const ClientReports* reports = nullptr);

  /// The planner of the next plans (validated first; throws InputError). Another kind plans
  /// afresh; the same kind goes on from the last route.
  void set_planner(const PlannerOptions& planner);
  PlannerOptions planner() const;

  std::vector<FieldCamera> cameras() const;
  /// What the pipeline of the next frame set is made of.
  ServicePipeline pipeline_setup() const;
  /// How many times the pipeline was replaced (replace_pipeline): a recorder that sees it change
  /// begins a file with the new setup.
  std::uint64_t pipeline_generation() const { return generation_; }
  /// Runs the pipeline made of `pipeline` (for the same cameras) from the next frame set on. Any
  /// thread. Throws InputError for another number of cameras.
  void replace_pipeline(ServicePipeline pipeline);
  /// Camera `index`'s last frame and detections; nullopt before its first frame. Any thread.
  std::optional<CameraView> camera_view(std::size_t index) const;

  /// {"frame_sets", "frame_sets_failed", "pipeline_ms", "plan_ms", "frame_sets_per_s",
  /// "last_error"}: the last frame set's times, and the rate over the last few.
  nlohmann::json health() const;

 private:
  // Runs the pipeline (`run`), keeps each camera's frame of `frames` (if any) as its view.
  std::uint64_t publish_result(const FrameSet& frames, NavigationHub& hub,
                               const ClientReports* reports,
                               const std::function<FrameSetResult(CourtPipeline&)>& run);
  // plan_mutex_ held; the update's seq (`published(seq)` runs before the hub's listeners).
  std::uint64_t plan_and_publish(NavigationHub& hub, const ClientReports* reports,
                                 const std::function<void(std::uint64_t)>& published = {});

  const Site& site_;
  mutable std::mutex pipeline_mutex_;  // guards pipeline_ and its setup (held while it runs)
  ServicePipeline setup_;
  std::unique_ptr<CourtPipeline> pipeline_;
  std::atomic<std::uint64_t> generation_{0};
  std::mutex plan_mutex_;  // guards the planner's use, the last world, its time, the route
  PlannerOptions planner_;
  std::optional<WorldModel> last_world_;  // nullopt before the first frame set
  std::optional<Route> previous_;
  mutable std::mutex mutex_;  // guards the figures below
  std::uint64_t frame_sets_ = 0, failed_ = 0;
  double pipeline_ms_ = 0.0, plan_ms_ = 0.0, rate_hz_ = 0.0;
  std::optional<std::chrono::steady_clock::time_point> last_;
  std::string last_error_;
  std::vector<std::optional<CameraView>> views_;  // per camera
  PlannerOptions next_planner_;                   // what planner() says, without waiting for a plan
};

}  // namespace ballsight
