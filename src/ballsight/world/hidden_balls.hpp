#pragma once
// Balls the robot's body hides. The corner cameras look down at a slant, so a ball right beside
// the robot (near a fence, where its own corner camera looks past it) can be hidden from every
// camera that would see it, from a few metres away; one frame set's world model then forgets it,
// the route with it, and the robot stops a metre short of it. Over a sequence of frame sets (the
// service, not one-off scenes), a ball the cameras stop seeing while the robot stands near it is
// remembered until it is seen again, the robot has moved away, or it has been missed for a few
// seconds; unless it vanished at the collector's mouth, which took it.

#include <vector>

#include "ballsight/world/world_model.hpp"

namespace ballsight {

struct HiddenBallOptions {
  /// Remembered while the robot's position is this close to it: the body (0.35 m high) hides
  /// the floor up to 0.35 x distance / camera height beyond it, 2.5 m for a camera 5 m high
  /// across the court.
  double near_robot_m = 3.0;
  int max_frame_sets = 50;  // and for this many frame sets at most (5 s at 10 Hz)
  /// A ball that vanishes this close to the collector's mouth (the site's 0.30 m ahead of the
  /// robot's position) was taken: not remembered.
  double mouth_ahead_m = 0.30;
  double taken_within_m = 0.45;  // half the 0.70 m collector and room
  double match_m = 0.30;         // seen again: a ball this close to it in a later frame set

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// What the memory carries from one frame set to the next.
struct HiddenBallState {
  struct Remembered {
    FusedBall ball;
    int frame_sets = 0;  // missed in this many in a row
  };
  std::vector<FusedBall> last_seen;  // the previous frame set's balls
  std::vector<Remembered> remembered;
};

class HiddenBallMemory {
 public:
  explicit HiddenBallMemory(const HiddenBallOptions& options = {});

  /// Adds the balls remembered as hidden to `world` (each its own collection site, with no
  /// cameras: none sees it), and
  /// remembers those of the previous frame set it no longer has near its robot.
  void apply(WorldModel& world);
  /// What it carries to the next frame set: the same world models after the same state give the
  /// same result.
  const HiddenBallState& state() const { return state_; }

 private:
  using Remembered = HiddenBallState::Remembered;
  HiddenBallOptions options_;
  HiddenBallState state_;
};

}  // namespace ballsight
