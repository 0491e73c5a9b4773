#include "ballsight/robot/pose_tracker.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

// Between two frame sets (0.1 s at 10 Hz) a collector moves a few cm: more than this is not a
// motion but a new odometry frame.
constexpr double kJumpM = 1.0;
constexpr double kJumpRad = kPi / 2.0;

Pose2D pose_of(const Rigid2& t) {
  return {t.translation, wrap_rad_pi(t.theta_rad)};
}

}  // namespace

void PoseTrackerOptions::validate() const {
  require(std::isfinite(max_unseen_m) && max_unseen_m >= 0.0, "max_unseen_m",
          "must not be negative");
  require(max_unseen_updates >= 0, "max_unseen_updates", "must not be negative");
}

PoseTracker::PoseTracker(const PoseTrackerOptions& options) : options_(options) {
  options_.validate();
}

std::optional<Pose2D> PoseTracker::at_capture(const std::optional<Pose2D>& seen,
                                              const Rigid2& moved) {
  previous_ = current_;
  previous_reading_ = reading_;
  reading_.reset();
  seen_ = seen.has_value();
  if (seen) {
    current_ = seen;
    unseen_m_ = previous_unseen_m_ = 0.0;
    unseen_updates_ = 0;
  } else if (current_) {
    current_ = pose_of(current_->field_from_robot() * moved);
    previous_unseen_m_ = unseen_m_;
    unseen_m_ += moved.translation.norm();
    if (++unseen_updates_ > options_.max_unseen_updates || unseen_m_ > options_.max_unseen_m) {
      current_.reset();
    }
  }
  return current_;
}

void PoseTracker::odometry(const Pose2D& reading) {
  reading_ = reading;
  if (seen_ || !current_ || !previous_ || !previous_reading_) return;
  const Rigid2 moved = previous_reading_->field_from_robot().inverse() * reading.field_from_robot();
  if (moved.translation.norm() > kJumpM || std::abs(wrap_rad_pi(moved.theta_rad)) > kJumpRad) {
    return;  // the prediction stands; the next reading moves on from this one
  }
  current_ = pose_of(previous_->field_from_robot() * moved);
  unseen_m_ = previous_unseen_m_ + moved.translation.norm();  // measured, not commanded
  if (unseen_m_ > options_.max_unseen_m) current_.reset();
}

}  // namespace ballsight
