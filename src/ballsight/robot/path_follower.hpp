#pragma once
// Following a planned route with a differential-drive collector. The route's waypoints are where
// the collector's mouth must pass (planning_input: the planned point is the mouth, a distance d
// ahead of the robot's reference point), so the follower steers the mouth, not the axle: a point
// ahead of a differential drive moves as P' = v h + d w h_perp (h the heading), so for a wanted
// velocity u of the mouth, v = u . h and w = (u . h_perp) / d, exactly (feedback linearisation;
// the mouth tracks the path itself, where pure pursuit cuts corners). u points at a carrot a
// look-ahead along the path from the mouth's progress, but never past the next waypoint (a ball
// is there: the mouth goes over it, not round the corner), and slows for the waypoint ahead and
// for the end of the path; a carrot behind the robot is turned to on the spot, except at the end
// of a short leg straight behind where there is no room to turn, which is reversed along
// (backing off the net or the fence). A turn on the
// spot keeps its direction until the carrot is ahead, through new routes and pose noise; a
// waypoint behind and within the mouth's circle round the axle (a ball beside the body) is first
// crept away from, since no turn brings the mouth over it.

#include <cstddef>
#include <optional>
#include <vector>

#include "ballsight/core/field_rect.hpp"
#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct FollowerOptions {
  double mouth_ahead_m = 0.30;  // d: the collector's mouth ahead of the pose
  double lookahead_m = 0.40;    // carrot distance along the path
  double max_speed_mps = 1.0;
  double max_turn_rate_rps = 1.5707963267948966;  // 90 deg/s
  double arrive_m = 0.05;                         // the end of the path is reached within this
  double slow_down_m = 0.6;                       // full speed until this close to the end
  double overshoot_m = 0.25;  // the path goes on this far past its last waypoint: the
                              // mouth must cross the last ball, not stop at it
  /// Where the robot has no room to turn on the spot (the net's lane, planning_input): with the
  /// mouth in it, a short leg straight behind is reversed along instead.
  std::optional<FieldRect> back_off_zone;
  /// The fence, and the area inside its lane (drivable_court.hpp): with the mouth outside that
  /// area a short leg straight behind is reversed along as in the back-off zone, and the path's
  /// overshoot ends at the fence.
  std::optional<FieldRect> fence;
  std::optional<FieldRect> inside_fence_lane;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

struct FollowCommand {
  double speed_mps = 0.0;
  double turn_rate_rps = 0.0;
  bool arrived = false;  // the mouth is at the path's end: the command is to stand still
};

class PathFollower {
 public:
  explicit PathFollower(const FollowerOptions& options = {});

  /// A new path (the latest route's waypoints, starting near the robot): progress starts again
  /// at its beginning. `path()` is it with the overshoot added.
  void set_path(std::vector<Vec2> waypoints);
  const std::vector<Vec2>& path() const { return path_; }

  /// The command for the robot at `pose` (its reference point and heading).
  FollowCommand command(const Pose2D& pose);

  /// Where along the path the mouth has got, in metres from its start.
  double progress_m() const { return progress_; }
  /// The point the last command steered the mouth for (the path's end when it arrived).
  const Vec2& carrot() const { return carrot_; }

 private:
  /// The point `s` metres along the path (clamped to its ends).
  Vec2 at(double s) const;

  FollowerOptions options_;
  std::vector<Vec2> path_;
  std::vector<double> cumulative_;  // path length up to each waypoint
  double progress_ = 0.0;
  Vec2 carrot_ = Vec2::Zero();
  double spin_ = 0.0;  // the direction of a turn on the spot under way (+1 left, -1 right)
  std::optional<Vec2> creep_from_;  // where creeping away from a waypoint too near began
  int creep_commands_ = 0;          // and the commands since
};

}  // namespace ballsight
