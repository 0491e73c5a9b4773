#pragma once
// The updates a robot link has received and not yet handed to the robot, with the link's status:
// what every RobotLink keeps whatever carries it. An update is delivered once (the same service's
// seq never goes back), a jump in seq counts as a gap, and a new service id is followed from
// wherever it starts. Thread-safe: the link's receiver delivers, the robot takes.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "ballsight/robot/robot_link.hpp"

namespace ballsight {

class LinkInbox {
 public:
  /// At most `keep` updates wait to be taken (the oldest are dropped).
  explicit LinkInbox(std::size_t keep) : keep_(keep) {}

  /// Keeps `update` unless it was delivered already; true when it was new.
  bool deliver(LinkUpdate update);
  /// The oldest update not taken (or the newest, dropping the rest), waiting up to `timeout`;
  /// nullopt at once after close().
  std::optional<LinkUpdate> take(std::chrono::milliseconds timeout, bool newest);
  /// Wakes every take() for good.
  void close();

  /// The last update delivered: its seq (0 before any) and its service's id.
  std::uint64_t last_seq() const;
  std::string service_id() const;

  LinkStatus status() const;
  /// Changes the status under the inbox's lock.
  void update_status(const std::function<void(LinkStatus&)>& change);

 private:
  const std::size_t keep_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<LinkUpdate> ready_;
  LinkStatus status_;
  std::uint64_t last_seq_ = 0;
  std::string service_id_;
  bool closed_ = false;
};

}  // namespace ballsight
