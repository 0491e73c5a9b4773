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
    recent_.push_back(std::move(update));
    if (recent_.size() > kKept) recent_.pop_front();
  }
  published_.notify_all();
  return seq;
}

std::optional<NavigationUpdate> NavigationHub::latest() const {
  const std::lock_guard lock(mutex_);
  if (recent_.empty()) return std::nullopt;
  return recent_.back();
}

std::optional<NavigationUpdate> NavigationHub::wait_after(std::uint64_t after,
                                                          std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  const auto newer = [&] { return !recent_.empty() && recent_.back().seq > after; };
  published_.wait_for(lock, timeout, [&] { return closed_ || newer(); });
  if (!newer()) return std::nullopt;
  // Sequence numbers are consecutive: the first newer one is at a known place.
  const std::uint64_t first = recent_.front().seq;
  return recent_[static_cast<std::size_t>(after + 1 > first ? after + 1 - first : 0)];
}

void NavigationHub::acknowledge(std::uint64_t seq) {
  const std::lock_guard lock(mutex_);
  const std::uint64_t newest = recent_.empty() ? 0 : recent_.back().seq;
  require(seq >= 1 && seq <= newest, "seq",
          "update " + std::to_string(seq) + " was not published (latest " + std::to_string(newest) +
              ")");
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
