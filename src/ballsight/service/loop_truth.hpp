#pragma once
// The closed loop's record (`serve --sim --truth-out FILE`, JSON lines) and its score. The first
// line is the scene as it began: {"kind": "scene", "seed", "balls": [{"id", "x_m", "y_m"}],
// "robot": {"x_m", "y_m", "heading_deg"}}. Then one line per vision tick: {"kind": "tick",
// "time_s", "seq" (the update published from the tick's frames, 0: none), "robot" (true pose
// after the tick), "command": {"speed_mps", "turn_rate_dps"}, "collected": [ball ids],
// "balls_left", "blocked", "held" (balls in the basket after it), "unloaded" (the basket was
// emptied in it), "clearance_m" (the body's nearest approach to the net, the fence or an obstacle
// in it), "published": {"robot" (as the cameras saw it, or null), "balls_seen",
// "waypoints_m"}, "removed_by_hand": [ball ids]}. And events as they happen: {"kind": "event",
// "time_s", "what"} (the service started or resumed, a camera failed). A restarted service resumes
// the court from this record.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/core/geometry.hpp"
#include "ballsight/sim/court_world.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct SceneBall {
  int id = 0;
  Vec2 position_m = Vec2::Zero();
};

/// What the service published for a tick.
struct PublishedUpdate {
  std::optional<Pose2D> robot;
  int balls_seen = 0;
  std::vector<Vec2> waypoints_m;
};

struct TruthTick {
  sim::WorldTick world;
  std::uint64_t seq = 0;
  sim::DriveCommand command;
  PublishedUpdate published;
  std::vector<int> removed_by_hand;  // reported collected while no robot drove, taken off
};

struct TruthEvent {
  double time_s = 0.0;
  std::string what;
};

struct LoopTruth {
  std::uint64_t seed = 0;
  std::vector<SceneBall> balls;  // as the scene began
  Pose2D robot_start;
  std::vector<TruthTick> ticks;
  std::vector<TruthEvent> events;
};

nlohmann::json scene_record(std::uint64_t seed, const std::vector<SceneBall>& balls,
                            const Pose2D& robot);
nlohmann::json tick_record(const TruthTick& tick);
nlohmann::json event_record(const TruthEvent& event);

/// Reads a record; throws InputError "<file>:<line>: ..." naming what is wrong. A last line cut
/// short (the service killed while writing it) is ignored.
LoopTruth read_loop_truth(const std::filesystem::path& file);
/// The same from a stream, `source` naming it in errors.
LoopTruth parse_loop_truth(std::istream& in, const std::string& source);

/// Cuts a last line the writer did not finish (it was killed), so that appending goes on cleanly.
void drop_unfinished_line(const std::filesystem::path& file);

/// A run scored on its truth: balls collected, when the last one was (or the last tick), the
/// distance driven until then, and whether the robot ever overlapped the net or the fence.
struct LoopScore {
  int balls = 0;
  int collected = 0;
  double time_s = 0.0;
  double distance_m = 0.0;
  bool all = false;
  bool never_overlapped = true;
  int blocked_ticks = 0;              // ticks in which the net or the fence stopped the robot
  int unloads = 0;                    // times the basket was emptied
  double min_clearance_m = INFINITY;  // the body's nearest approach to them over the run
};

LoopScore score_loop(int balls, const Pose2D& start, const std::vector<sim::WorldTick>& ticks,
                     const sim::RobotFootprint& footprint);
/// The same for a run read back from its record.
LoopScore score_loop(const LoopTruth& truth, const sim::RobotFootprint& footprint);

/// The simulated collector's footprint for a site's robot (the simulator's box, its collector).
sim::RobotFootprint collector_footprint(const SiteRobot& robot);

}  // namespace ballsight
