#include "ballsight/dds/court_topics.hpp"

#include <algorithm>

#include "ballsight/dds/court_messages.hpp"
#include "ballsight/dds/robot_messages.hpp"

namespace ballsight::dds {
namespace {

const TopicQos kLatest{true, 1};  // transient-local, keep last 1
// Updates written at most when several came at once: as many as the hub keeps, so that a robot
// on `navigation` misses none that an HTTP client would get.
constexpr std::uint64_t kBehind = NavigationHub::kKept;

}  // namespace

CourtTopics::CourtTopics(const Participant& participant, NavigationHub& hub,
                         std::function<nlohmann::json()> health, const CourtTopicsOptions& options)
    : hub_(hub),
      health_(std::move(health)),
      options_(options),
      robot_pose_(participant, "robot_pose"),
      balls_(participant, "balls", kLatest),
      ball_estimates_(participant, "ball_estimates", kLatest),
      route_(participant, "route", kLatest),
      navigation_(participant, kNavigationTopic, kNavigationQos),
      diagnostics_(participant, "diagnostics") {
  if (options_.camera_detections) {
    for (const std::string& camera : options_.detection_cameras)
      detections_.emplace(camera, std::make_unique<Writer<CameraDetectionsMsg>>(
                                      participant, detections_topic(camera)));
  }
  listener_ = hub_.add_listener([this](std::uint64_t seq) {
    {
      const std::lock_guard lock(mutex_);
      pending_seq_ = seq;
    }
    wake_.notify_one();
  });
  thread_ = std::thread([this] { run(); });
}

CourtTopics::~CourtTopics() {
  hub_.remove_listener(listener_);
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void CourtTopics::run() {
  std::uint64_t written_seq = 0;
  auto next_health = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_);
  while (!stop_) {
    wake_.wait_until(lock, next_health, [&] { return stop_ || pending_seq_ != written_seq; });
    if (stop_) break;
    const std::uint64_t seq = pending_seq_;
    lock.unlock();
    // Every update in turn (those published while one was written too; the hub keeps the
    // recent ones): a subscriber sees the sequence the court made, not only its latest.
    for (std::uint64_t s = std::max(written_seq + 1, seq > kBehind ? seq - kBehind : 1); s <= seq;
         ++s) {
      if (const std::optional<NavigationUpdate> update = hub_.find(s))
        guarded("update " + std::to_string(s), [&] { write(*update); });
    }
    written_seq = seq;
    if (std::chrono::steady_clock::now() >= next_health) {
      guarded("diagnostics", [&] { write_health(); });
      next_health = std::chrono::steady_clock::now() + options_.health_period;
    }
    lock.lock();
  }
}

void CourtTopics::guarded(const std::string& what, const std::function<void()>& write) {
  try {
    write();
  } catch (const std::exception& e) {  // DDS refused: say so, the next update is written anew
    ++failed_;
    if (options_.on_error) options_.on_error(what + ": " + e.what());
  }
}

void CourtTopics::write(const NavigationUpdate& update) {
  MessageArena arena;
  // The robot's first: a refused write of an observer's topic below does not cost it its update.
  navigation_.write(
      navigation_update_message(update, hub_.service_id(), options_.ball_radius_m, arena));
  if (const std::optional<PoseStampedMsg> pose = robot_pose_message(update, arena))
    robot_pose_.write(*pose);
  balls_.write(balls_message(update, options_.ball_radius_m, arena));
  ball_estimates_.write(ball_estimates_message(update, options_.ball_radius_m, arena));
  route_.write(route_message(update, arena));
  if (options_.camera_detections) write_detections(update);
  ++written_;
}

void CourtTopics::write_detections(const NavigationUpdate& update) {
  for (const CameraFrameDetections& frame : options_.camera_detections(update)) {
    const auto writer = detections_.find(frame.camera);
    if (writer == detections_.end()) continue;  // not one of the cameras named in the options
    MessageArena arena;
    writer->second->write(camera_detections_message(frame, arena));
  }
}

void CourtTopics::write_health() {
  MessageArena arena;
  diagnostics_.write(
      diagnostics_message(health_(), options_.diagnostics_prefix, utc_now_ns(), arena));
}

}  // namespace ballsight::dds
