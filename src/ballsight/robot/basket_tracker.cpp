#include "ballsight/robot/basket_tracker.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

void BasketOptions::validate() const {
  require(std::isfinite(stop_within_m) && stop_within_m > 0.0, "stop_within_m", "must be positive");
  require(std::isfinite(stand_within_m) && stand_within_m >= stop_within_m, "stand_within_m",
          "must not be less than stop_within_m");
  require(std::isfinite(max_accel_mps2) && max_accel_mps2 > 0.0, "max_accel_mps2",
          "must be positive");
}

BasketTracker::BasketTracker(const BasketOptions& options) : options_(options) {
  options_.validate();
}

void BasketTracker::answered(int taken, std::optional<int> court_held) {
  const int before = held_;
  held_ = court_held ? *court_held : held_ + taken;
  if (held_ < before + taken) ++unloads_;
}

std::optional<int> BasketTracker::to_tell(const std::string& service_id) {
  if (service_id != service_id_) {  // a service that began knows an empty basket
    service_id_ = service_id;
    told_held_ = 0;
  }
  if (held_ == told_held_) return std::nullopt;
  return held_;
}

bool BasketTracker::standing(const LinkUpdate& u, const Vec2& mouth) {
  if (!u.unload_first_m || held_ == 0) {
    standing_ = false;
    return false;
  }
  const double d = (mouth - *u.unload_first_m).norm();
  standing_ = d <= (standing_ ? options_.stand_within_m : options_.stop_within_m);
  return standing_;
}

FollowCommand BasketTracker::approach(const LinkUpdate& u, const Vec2& mouth,
                                      FollowCommand wanted) const {
  if (!u.unload_first_m || held_ == 0 || wanted.speed_mps <= 0.0) return wanted;
  // The speed from which braking stops the robot at the point.
  const double d = (mouth - *u.unload_first_m).norm();
  const double limit = std::sqrt(2.0 * options_.max_accel_mps2 * d);
  if (wanted.speed_mps <= limit) return wanted;
  const double scale = limit / wanted.speed_mps;
  wanted.speed_mps *= scale;
  wanted.turn_rate_rps *= scale;
  return wanted;
}

}  // namespace ballsight
