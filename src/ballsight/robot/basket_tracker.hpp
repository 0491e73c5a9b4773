#pragma once
// The collector's basket on the robot's side (docs/robot-link.md, "The basket"): how many balls it
// holds (the court's sensor, else counted), what the service was told of it (told again until it
// accepts, and told again when the service restarted), and the stop to empty it: when the route
// empties the basket before its next ball, the robot slows so as to stop with its mouth at the
// unload point, and stands there until the basket is empty.

#include <optional>
#include <string>

#include "ballsight/core/geometry.hpp"
#include "ballsight/robot/path_follower.hpp"
#include "ballsight/robot/robot_link.hpp"

namespace ballsight {

struct BasketOptions {
  double stop_within_m = 0.3;   // the mouth this near the unload point: the robot stands
  double stand_within_m = 0.5;  // and keeps standing while it is this near (the court's reach)
  double max_accel_mps2 = 1.0;  // braking, to stop at the point

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class BasketTracker {
 public:
  explicit BasketTracker(const BasketOptions& options = {});

  /// The court's answer to a wheel command: `taken` balls came in, and the basket holds
  /// `court_held` when the court says (else the count goes on).
  void answered(int taken, std::optional<int> court_held);
  int held() const { return held_; }
  int unloads() const { return unloads_; }

  /// The count the service `service_id` should be told now (nullopt: it knows it; a service
  /// that restarted knows an empty basket).
  std::optional<int> to_tell(const std::string& service_id);
  /// The service accepted `held`.
  void told(int held) { told_held_ = held; }

  /// Whether the robot, its mouth at `mouth`, stands to empty the basket for update `u`.
  bool standing(const LinkUpdate& u, const Vec2& mouth);
  /// `wanted` slowed (speed and turn alike) so that the robot stops with its mouth at the unload
  /// point the route goes to first; as it is otherwise.
  FollowCommand approach(const LinkUpdate& u, const Vec2& mouth, FollowCommand wanted) const;

 private:
  BasketOptions options_;
  int held_ = 0;
  int unloads_ = 0;
  std::string service_id_;  // the service told_held_ is of
  int told_held_ = 0;
  bool standing_ = false;
};

}  // namespace ballsight
