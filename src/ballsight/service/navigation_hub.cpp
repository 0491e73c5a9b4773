#include "ballsight/service/navigation_hub.hpp"

#include <algorithm>
#include <random>
#include <utility>

#include "ballsight/core/closest_pairs.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

std::string random_hex(int digits) {
  std::random_device random;
  constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (int i = 0; i < digits; ++i) out += kHex[random() % 16];
  return out;
}

NavigationHub::NavigationHub() : service_id_(random_hex(16)) {}

std::uint64_t NavigationHub::publish(NavigationUpdate update,
                                     const std::function<void(std::uint64_t)>& before_listeners) {
  std::uint64_t seq = 0;
  {
    const std::lock_guard lock(mutex_);
    seq = next_seq_++;
    update.seq = seq;
    update.published_ns = utc_now_ns();
    recent_.push_back(std::move(update));
    if (recent_.size() > kKept) recent_.pop_front();
  }
  if (before_listeners) before_listeners(seq);
  const std::lock_guard lock(listeners_mutex_);
  for (const auto& [id, listener] : listeners_) listener(seq);
  return seq;
}

int NavigationHub::add_listener(std::function<void(std::uint64_t)> listener) {
  const std::lock_guard lock(listeners_mutex_);
  listeners_.emplace_back(next_listener_, std::move(listener));
  return next_listener_++;
}

void NavigationHub::remove_listener(int id) {
  const std::lock_guard lock(listeners_mutex_);
  std::erase_if(listeners_, [id](const auto& l) { return l.first == id; });
}

std::optional<NavigationUpdate> NavigationHub::latest() const {
  const std::lock_guard lock(mutex_);
  if (recent_.empty()) return std::nullopt;
  return recent_.back();
}

namespace {

/// Where the first update newer than `after` is in `recent` (sequence numbers are consecutive);
/// recent.size() when there is none.
std::size_t first_index_after(const std::deque<NavigationUpdate>& recent, std::uint64_t after) {
  if (recent.empty() || recent.back().seq <= after) return recent.size();
  const std::uint64_t first = recent.front().seq;
  return static_cast<std::size_t>(after + 1 > first ? after + 1 - first : 0);
}

/// Drops the oldest of `items` beyond the newest `n`.
template <class T>
void keep_newest(std::vector<T>& items, std::size_t n) {
  if (items.size() > n) {
    items.erase(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(items.size() - n));
  }
}

std::vector<Vec2> positions(const std::vector<External<Vec2>>& reports) {
  std::vector<Vec2> out;
  out.reserve(reports.size());
  for (const External<Vec2>& r : reports) out.push_back(r.value);
  return out;
}

}  // namespace

std::optional<NavigationUpdate> NavigationHub::first_after(std::uint64_t after) const {
  const std::lock_guard lock(mutex_);
  const std::size_t i = first_index_after(recent_, after);
  if (i == recent_.size()) return std::nullopt;
  return recent_[i];
}

std::optional<NavigationUpdate> NavigationHub::find(std::uint64_t seq) const {
  std::optional<NavigationUpdate> u = seq > 0 ? first_after(seq - 1) : std::nullopt;
  if (u && u->seq != seq) u.reset();
  return u;
}

std::vector<NavigationUpdate> NavigationHub::all_after(std::uint64_t after) const {
  const std::lock_guard lock(mutex_);
  const auto first =
      recent_.begin() + static_cast<std::ptrdiff_t>(first_index_after(recent_, after));
  return {first, recent_.end()};
}

std::uint64_t NavigationHub::latest_seq() const {
  const std::lock_guard lock(mutex_);
  return newest_seq();
}

void NavigationHub::acknowledge(std::uint64_t seq) {
  const std::lock_guard lock(mutex_);
  const std::uint64_t newest = newest_seq();
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
  const std::int64_t now = utc_now_ns();
  for (const Vec2& p : positions) {
    collected_.push_back({p, now});
    for_hand_.push_back(p);
  }
  keep_newest(collected_, kMaxCollected);
  keep_newest(for_hand_, kMaxCollected);
}

void NavigationHub::mark_unreachable(const std::vector<Vec2>& positions,
                                     const std::string& reason) {
  const std::lock_guard lock(mutex_);
  for (const Vec2& p : positions) unreachable_.push_back({p, reason});
  keep_newest(unreachable_, kMaxUnreachable);
}

void NavigationHub::set_basket(int held) {
  const std::lock_guard lock(mutex_);
  basket_ = External<int>{held, utc_now_ns()};
}

std::vector<Vec2> NavigationHub::take_for_hand() {
  const std::lock_guard lock(mutex_);
  return std::exchange(for_hand_, {});
}

std::vector<bool> taken_by_reports(const std::vector<Vec2>& balls,
                                   const std::vector<Vec2>& collected) {
  std::vector<bool> taken(balls.size(), false);
  for (const PointPair& p : closest_pairs(collected, balls, kCollectedMatchM)) taken[p.b] = true;
  return taken;
}

ClientReports NavigationHub::reports() const {
  const std::lock_guard lock(mutex_);
  return {robot_, balls_, positions(collected_), basket_, unreachable_};
}

void NavigationHub::frames_fused(std::int64_t capture_ns) {
  const std::lock_guard lock(mutex_);
  std::erase_if(collected_, [&](const External<Vec2>& c) { return c.set_ns < capture_ns; });
}

std::vector<Vec2> NavigationHub::collected() const {
  const std::lock_guard lock(mutex_);
  return positions(collected_);
}

}  // namespace ballsight
