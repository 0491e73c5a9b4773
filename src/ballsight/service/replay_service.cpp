#include "ballsight/service/replay_service.hpp"

#include <chrono>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/service/run_replay.hpp"

namespace ballsight {

void ReplayServiceOptions::validate() const {
  require(speed >= 0.0 && speed <= 1000.0, "--speed",
          "must be 0 (as fast as it goes) to 1000 times the recorded pace");
}

ReplayCourtService::ReplayCourtService(const std::filesystem::path& file,
                                       const ReplayServiceOptions& options)
    : run_(file), options_(options) {
  options_.validate();
  const RunSetup& setup = run_.setup();
  publisher_ = std::make_unique<UpdatePublisher>(setup.site, setup.pipeline, setup.planner);
  frames_.resize(setup.pipeline.cameras.size());
}

ReplayCourtService::~ReplayCourtService() = default;

void ReplayCourtService::run(NavigationHub& hub, const std::atomic<bool>& stop) {
  using Clock = std::chrono::steady_clock;
  UpdateReplayer replayer(*publisher_, run_.setup().planner, {options_.planner});
  const Clock::time_point started = Clock::now();
  std::optional<std::int64_t> first_ns;  // the first update's publish time
  run_.for_each_update([&](const RecordedUpdate& recorded) {
    if (!first_ns) first_ns = recorded.published_ns;
    if (options_.speed > 0.0) {
      const auto due =
          started + std::chrono::nanoseconds(static_cast<std::int64_t>(
                        static_cast<double>(recorded.published_ns - *first_ns) / options_.speed));
      while (!stop && Clock::now() < due)
        std::this_thread::sleep_for(
            std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(50)));
    }
    if (stop) return false;
    std::string why;
    const bool replayed = replayer.feed(recorded, hub, why) != 0;
    const std::lock_guard lock(mutex_);
    ++updates_;
    replayed_ += replayed;
    for (std::size_t k = 0; k < frames_.size() && k < recorded.frames.cameras.size(); ++k)
      frames_[k] += !recorded.frames.cameras[k].image.empty();
    return true;
  });
  {
    const std::lock_guard lock(mutex_);
    finished_ = !stop;
  }
  while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

void ReplayCourtService::republish(NavigationHub& hub) {
  publisher_->republish(hub);
}

nlohmann::json ReplayCourtService::health() const {
  nlohmann::json h = publisher_->health();
  const std::lock_guard lock(mutex_);
  nlohmann::json cameras = nlohmann::json::array();
  const std::vector<std::string>& names = run_.camera_names();
  for (std::size_t k = 0; k < names.size(); ++k) {
    cameras.push_back({{"name", names[k]},
                       {"state", finished_ ? "finished" : "replaying"},
                       {"frames", frames_[k]}});
  }
  h["cameras"] = cameras;
  h["replay"] = {{"file", run_.path().string()},
                 {"speed", options_.speed},
                 {"updates", updates_},
                 {"replayed", replayed_},
                 {"not_replayed", updates_ - replayed_},
                 {"finished", finished_}};
  return h;
}

}  // namespace ballsight
