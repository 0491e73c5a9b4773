#pragma once
// The navigation service's state between the court pipeline (which publishes one update per
// world model) and its clients (which read, long-poll, acknowledge, and report balls they picked
// up or positions of their own). The report's four web methods and flag (tennis-ball report,
// sections 7.9-7.10) become: the latest update with a sequence number, the sequence number the
// robot acknowledged, and external robot pose and balls a client may set. Thread-safe.

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/core/utc_clock.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight {

/// `digits` random hexadecimal digits (std::random_device).
std::string random_hex(int digits);

/// A ball the robot gave up on (it could not reach it after a bounded number of tries), where it
/// was and why: the planner leaves balls there out.
struct UnreachableMark {
  Vec2 position_m = Vec2::Zero();
  std::string reason;
};

/// A pose or ball list a client set (PUT), with when it was set.
template <class T>
struct External {
  T value;
  std::int64_t set_ns = 0;  // UTC
};

/// What clients told the service, which a plan weighs against what the cameras saw.
struct ClientReports {
  std::optional<External<Pose2D>> robot;             // a pose a client set
  std::optional<External<std::vector<Vec2>>> balls;  // a ball list a client set
  /// Where the robot reported balls collected that no frames captured since have been fused
  /// into a world model (the frames before the report may still show them).
  std::vector<Vec2> collected;
  /// The balls in the robot's basket, as it last reported them (none reported: empty).
  std::optional<External<int>> basket;
  /// Balls the robot marked unreachable.
  std::vector<UnreachableMark> unreachable;
};

/// One published value: what the cameras saw and where the robot should go.
struct NavigationUpdate {
  std::uint64_t seq = 0;             // 1, 2, ... in publishing order
  std::int64_t capture_time_ns = 0;  // UTC, when the frames behind it were captured
  std::int64_t published_ns = 0;     // UTC, when it was published
  WorldModel world;
  Route route;
  /// What clients had reported when it was planned (a recording keeps it, to replay the plan);
  /// its `unreachable` are the balls the robot gave up on, oldest first.
  ClientReports reports;
};

/// A ball reported collected is a ball seen this close to where it was reported.
constexpr double kCollectedMatchM = 0.30;

/// Per ball of `balls`: whether one of the reports `collected` accounts for it. Each report takes
/// one ball, the nearest within kCollectedMatchM that a nearer report did not take (the closest
/// report-ball pairs first): a report in a cluster of balls stands for one ball, not the cluster.
std::vector<bool> taken_by_reports(const std::vector<Vec2>& balls,
                                   const std::vector<Vec2>& collected);

class NavigationHub {
 public:
  NavigationHub();

  /// Random, fixed for this hub's life: a client that sees it change knows the service restarted
  /// and its sequence numbers began again.
  const std::string& service_id() const { return service_id_; }

  /// Publishes `update` (its seq and published time are assigned) and tells every listener;
  /// `before_listeners(seq)`, when given, runs first (to store what goes with the update).
  std::uint64_t publish(NavigationUpdate update,
                        const std::function<void(std::uint64_t)>& before_listeners = {});
  std::optional<NavigationUpdate> latest() const;
  /// The latest update's seq without copying it; 0 before the first.
  std::uint64_t latest_seq() const;
  /// The first update newer than `after` (the oldest one kept, when `after` is older than
  /// that); nullopt when there is none yet.
  std::optional<NavigationUpdate> first_after(std::uint64_t after) const;
  /// The update `seq`, while it is kept; nullopt otherwise.
  std::optional<NavigationUpdate> find(std::uint64_t seq) const;
  /// Every kept update newer than `after`, oldest first.
  std::vector<NavigationUpdate> all_after(std::uint64_t after) const;

  /// Called with the new seq after every publish, from the publishing thread (it must return
  /// quickly: hand the work over). Returns an id for `remove_listener`.
  int add_listener(std::function<void(std::uint64_t seq)> listener);
  void remove_listener(int id);

  /// Updates kept for clients that read behind the newest (a reader further behind skips to the
  /// oldest kept; the gap in seq says how many it missed).
  static constexpr std::size_t kKept = 64;

  /// Marks update `seq` read; throws InputError when it was not published yet.
  void acknowledge(std::uint64_t seq);
  std::uint64_t acknowledged() const;

  void set_robot(const Pose2D& pose);
  std::optional<External<Pose2D>> robot() const;
  void set_balls(std::vector<Vec2> balls);
  std::optional<External<std::vector<Vec2>>> balls() const;
  /// Balls the robot reports collected (stamped now): the planner leaves them out until a world
  /// model of frames captured after the report is made. At most kMaxCollected are kept (the
  /// oldest go first).
  void add_collected(const std::vector<Vec2>& positions);
  /// The balls the robot's basket holds now (it reports them with its collected balls, and 0
  /// after emptying it).
  void set_basket(int held);
  /// Balls the robot gave up on: left out of every plan from now on (the balls seen within
  /// kCollectedMatchM of a mark). At most kMaxUnreachable are kept (the oldest go first).
  void mark_unreachable(const std::vector<Vec2>& positions, const std::string& reason);
  static constexpr std::size_t kMaxUnreachable = 256;
  std::vector<Vec2> collected() const;
  /// The robot pose, ball list and collected balls clients reported, as one consistent value.
  ClientReports reports() const;
  /// A world model of frames captured at `capture_ns` (UTC) was made: the reports made before
  /// then are forgotten, since those frames show what the robot took gone; a ball they still
  /// show there was not taken, or is another one, and is planned again.
  void frames_fused(std::int64_t capture_ns);
  /// The reports made since the last call, each handed out once (a simulated court with no robot
  /// driving takes their balls off by hand; at most kMaxCollected wait).
  std::vector<Vec2> take_for_hand();

  static constexpr std::size_t kMaxCollected = 4096;

 private:
  std::uint64_t newest_seq() const { return recent_.empty() ? 0 : recent_.back().seq; }  // locked

  std::string service_id_;
  mutable std::mutex mutex_;
  std::mutex listeners_mutex_;  // publish calls listeners outside mutex_
  std::vector<std::pair<int, std::function<void(std::uint64_t)>>> listeners_;
  int next_listener_ = 1;
  std::deque<NavigationUpdate> recent_;  // the last kKept updates, oldest first
  std::uint64_t next_seq_ = 1;
  std::uint64_t acknowledged_ = 0;
  std::optional<External<Pose2D>> robot_;
  std::optional<External<std::vector<Vec2>>> balls_;
  std::vector<External<Vec2>> collected_;
  std::optional<External<int>> basket_;
  std::vector<UnreachableMark> unreachable_;
  std::vector<Vec2> for_hand_;
};

}  // namespace ballsight
