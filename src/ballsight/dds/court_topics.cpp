#include "ballsight/dds/court_topics.hpp"

#include "ballsight/dds/court_messages.hpp"

namespace ballsight::dds {
namespace {

const TopicQos kLatest{true, 1};  // transient-local, keep last 1

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
      diagnostics_(participant, "diagnostics"),
      participant_(participant) {
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
    if (seq != written_seq) {
      if (const std::optional<NavigationUpdate> update = hub_.find(seq)) write(*update);
      written_seq = seq;
    }
    if (std::chrono::steady_clock::now() >= next_health) {
      write_health();
      next_health = std::chrono::steady_clock::now() + options_.health_period;
    }
    lock.lock();
  }
}

void CourtTopics::write(const NavigationUpdate& update) {
  MessageArena arena;
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
    std::unique_ptr<Writer<CameraDetectionsMsg>>& writer = detections_[frame.camera];
    if (!writer)
      writer = std::make_unique<Writer<CameraDetectionsMsg>>(participant_,
                                                             detections_topic(frame.camera));
    MessageArena arena;
    writer->write(camera_detections_message(frame, arena));
  }
}

void CourtTopics::write_health() {
  MessageArena arena;
  diagnostics_.write(
      diagnostics_message(health_(), options_.diagnostics_prefix, utc_now_ns(), arena));
}

}  // namespace ballsight::dds
