#pragma once
// Obstacles the robot stands beside. The world model leaves out the floor round the robot's body
// (its own views are there: world/floor_obstacles.hpp), so a person the robot comes near drops out
// of the world model just when it matters. Over a sequence of frame sets, an obstacle that
// vanishes while the robot is near it is remembered until it is seen again, the robot has moved
// away from it, or for a while at most (also while the robot itself is not seen).

#include <vector>

#include "ballsight/world/world_model.hpp"

namespace ballsight {

struct HiddenObstacleOptions {
  /// Remembered while the robot's position is this close to its edge: the floor left out round
  /// the body (0.4 m beyond it) and the body's own half diagonal, with room.
  double near_robot_m = 1.2;
  int max_frame_sets = 100;  // and for this many frame sets at most (10 s at 10 Hz)
  double match_m = 0.5;      // seen again: an obstacle centred this close to it

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class HiddenObstacleMemory {
 public:
  explicit HiddenObstacleMemory(const HiddenObstacleOptions& options = {});

  /// Adds the obstacles remembered as hidden to `world` (with no cameras: none sees it), and
  /// remembers those of the previous frame set it no longer has near its robot.
  void apply(WorldModel& world);

 private:
  struct Remembered {
    FloorObstacle obstacle;
    int frame_sets = 0;  // missed in this many in a row
  };
  HiddenObstacleOptions options_;
  std::vector<FloorObstacle> last_seen_;
  std::vector<Remembered> remembered_;
};

}  // namespace ballsight
