#pragma once
// `ballsight serve --replay FILE.mcap`: a recorded run served as if live. The recorded frames go
// through this build's pipeline and planner (UpdateReplayer: the reports each update was planned
// with, the planner as recorded), at the pace they were published (times --speed), and the
// updates are published into the hub like any court service's: the dashboard, API v1, Foxglove
// and a recorder see a live court. Capture times are the recording's. When the file ends the
// service keeps its last update until it is stopped.

#include <atomic>
#include <filesystem>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>

#include "ballsight/service/court_service.hpp"
#include "ballsight/service/recorded_run.hpp"

namespace ballsight {

struct ReplayServiceOptions {
  /// Recorded time runs this many times faster than wall time; 0: as fast as it goes.
  double speed = 1.0;
  /// Plan with this planner instead of the recorded one.
  std::optional<PlannerKind> planner;

  /// Throws InputError naming the option.
  void validate() const;
};

class ReplayCourtService : public CourtService {
 public:
  /// Opens the recording (InputError naming the file and what is wrong).
  ReplayCourtService(const std::filesystem::path& file, const ReplayServiceOptions& options);
  ~ReplayCourtService() override;

  const Site& site() const override { return run_.setup().site; }
  void run(NavigationHub& hub, const std::atomic<bool>& stop) override;
  /// Clients' reports (the hub's) weighed against the last replayed world.
  void republish(NavigationHub& hub) override;
  /// {"cameras": [{"name", "state": "replaying" or "finished", "frames"}], "replay": {"file",
  /// "speed", "updates", "replayed", "not_replayed", "finished"}, and UpdatePublisher::health()'s
  /// figures}.
  nlohmann::json health() const override;

 protected:
  UpdatePublisher& publisher() const override { return *publisher_; }

 private:
  RecordedRun run_;
  ReplayServiceOptions options_;
  std::unique_ptr<UpdatePublisher> publisher_;
  mutable std::mutex mutex_;  // guards the figures below
  std::uint64_t updates_ = 0, replayed_ = 0;
  std::vector<std::uint64_t> frames_;  // per camera
  bool finished_ = false;
};

}  // namespace ballsight
