#pragma once
// The robot's pose between the cameras' fixes (docs/robot-link.md, "Where the robot is"). Each
// navigation update brings the cameras' pose of the robot at the update's capture, when they saw
// it; near a mast or among players they may not. Between fixes the robot carries its last pose on
// by its own motion, as a real robot dead-reckons between localisation fixes: first by the
// command its wheels were carrying out (a prediction, when the update arrives), then by its
// wheels' odometry at the same capture once the body reports it (the simulated court answers
// every wheel command with it). A camera fix replaces the estimate outright (the cameras' pose
// is unbiased and a few cm off; odometry drifts without bound). Dead reckoning ends, and the pose
// is unknown again, after a bounded distance or number of updates without a fix.

#include <optional>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct PoseTrackerOptions {
  /// Dead reckoning for at most this far since the last fix (odometry's 1 % a metre: 8 cm) and
  /// this many frame sets (60 s at the cameras' 10 Hz).
  double max_unseen_m = 8.0;
  int max_unseen_updates = 600;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class PoseTracker {
 public:
  explicit PoseTracker(const PoseTrackerOptions& options = {});

  /// A new frame set's update: `seen` is the cameras' pose at its capture (nullopt: not seen),
  /// `moved` the robot's own prediction of how it moved since the previous capture (in its frame
  /// at that capture). Returns the pose at the capture, or nullopt when none is known.
  std::optional<Pose2D> at_capture(const std::optional<Pose2D>& seen, const Rigid2& moved);
  /// The wheels' odometry (in its own frame) at the same capture: where the cameras did not see
  /// the robot, the estimate becomes the previous capture's moved on by what the wheels measured.
  /// A reading that jumps (a restarted court's odometry) only restarts the odometry.
  void odometry(const Pose2D& reading);

  /// The pose at the last capture (nullopt: unknown).
  const std::optional<Pose2D>& pose() const { return current_; }
  /// Whether that pose is the cameras' (false: dead reckoned, or unknown).
  bool seen() const { return seen_; }

 private:
  PoseTrackerOptions options_;
  std::optional<Pose2D> current_, previous_;          // at this capture and at the one before
  std::optional<Pose2D> reading_, previous_reading_;  // the odometry at those captures
  bool seen_ = false;
  double unseen_m_ = 0.0;           // travelled since the last fix
  double previous_unseen_m_ = 0.0;  // until the capture before
  int unseen_updates_ = 0;
};

}  // namespace ballsight
