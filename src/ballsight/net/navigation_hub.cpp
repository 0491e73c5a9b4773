#include "ballsight/net/navigation_hub.hpp"

#include "ballsight/core/error.hpp"

namespace ballsight {

std::int64_t utc_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::uint64_t NavigationHub::publish(NavigationUpdate update) {
  std::uint64_t seq = 0;
  {
    const std::lock_guard lock(mutex_);
    seq = next_seq_++;
    update.seq = seq;
    update.published_ns = utc_now_ns();
    latest_ = std::move(update);
  }
  published_.notify_all();
  return seq;
}

std::optional<NavigationUpdate> NavigationHub::latest() const {
  const std::lock_guard lock(mutex_);
  return latest_;
}

std::optional<NavigationUpdate> NavigationHub::wait_after(std::uint64_t after,
                                                          std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  published_.wait_for(lock, timeout, [&] { return closed_ || (latest_ && latest_->seq > after); });
  if (latest_ && latest_->seq > after) return latest_;
  return std::nullopt;
}

void NavigationHub::acknowledge(std::uint64_t seq) {
  const std::lock_guard lock(mutex_);
  require(latest_ && seq >= 1 && seq <= latest_->seq, "seq",
          "update " + std::to_string(seq) + " was not published (latest " +
              std::to_string(latest_ ? latest_->seq : 0) + ")");
  acknowledged_ = std::max(acknowledged_, seq);
}

std::uint64_t NavigationHub::acknowledged() const {
  const std::lock_guard lock(mutex_);
  return acknowledged_;
}

void NavigationHub::set_robot(const Pose2D& pose) {
  const std::lock_guard lock(mutex_);
  robot_ = External<Pose2D>{pose, utc_now_ns()};
}

std::optional<External<Pose2D>> NavigationHub::robot() const {
  const std::lock_guard lock(mutex_);
  return robot_;
}

void NavigationHub::set_balls(std::vector<Vec2> balls) {
  const std::lock_guard lock(mutex_);
  balls_ = External<std::vector<Vec2>>{std::move(balls), utc_now_ns()};
}

std::optional<External<std::vector<Vec2>>> NavigationHub::balls() const {
  const std::lock_guard lock(mutex_);
  return balls_;
}

void NavigationHub::add_collected(const std::vector<Vec2>& positions) {
  const std::lock_guard lock(mutex_);
  collected_.insert(collected_.end(), positions.begin(), positions.end());
}

std::vector<Vec2> NavigationHub::collected() const {
  const std::lock_guard lock(mutex_);
  return collected_;
}

void NavigationHub::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  published_.notify_all();
}

}  // namespace ballsight
