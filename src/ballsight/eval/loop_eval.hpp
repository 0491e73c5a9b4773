#pragma once
// `ballsight eval loop`: the closed loop on simulated scenes, per system: the report's pipeline
// with its priority planner ("report"), ballsight's pipeline with the priority planner
// ("priority"), and ballsight's pipeline and planner ("ballsight"). Each run is the real
// loop in one process: the simulated court service and the collector driving over a RobotLink
// (`ballsight eval loop`: API v1 on a free loopback port, net/loopback_robot_link.hpp), scored on
// the court's recorded truth.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/robot/robot_link.hpp"
#include "ballsight/service/run_recorder.hpp"
#include "ballsight/service/simulated_service.hpp"

namespace ballsight::eval {

struct LoopSystem {
  std::string name;
  bool report_pipeline = false;
  PlannerKind planner = PlannerKind::ballsight;
};

/// report, priority, ballsight.
const std::vector<LoopSystem>& loop_systems();

/// How a scene's balls lie: scattered on both sides of the net and some in the run-off
/// ("uniform"), three quarters of them in clusters of 2-4 touching balls, the rest scattered
/// ("clustered", as after practice), or, beside up to four balls by the robot, all in a line along
/// the net, along the fence, or around the net posts (sim::BallLayout).
struct LoopLayout {
  bool clustered = false;
  sim::BallLayout others = sim::BallLayout::scattered;

  std::string name() const;
};

/// The layouts scene k of an evaluation takes in turn (k modulo their number): uniform,
/// clustered, along the net, along the fence, around the net posts.
const std::vector<LoopLayout>& loop_layouts();

/// The obstacles scene k of an evaluation has in the default mix (k modulo 3): none, a person
/// standing and a bag, a person walking across.
sim::ObstacleOptions loop_obstacles(int k);
/// "none", or a scene's obstacles joined by '+': "person+bag", "walker".
std::string obstacles_name(const std::vector<sim::CourtObstacle>& obstacles);

struct LoopScene {
  std::uint64_t seed = 1;
  int balls = 10;
  LoopLayout layout;
  sim::ObstacleOptions obstacles;
  std::function<void(sim::CourtScene&)> arrange;  // SimulatedCourtOptions::arrange
};

struct LoopRun {
  std::string system;
  std::uint64_t seed = 0;
  std::string layout;     // LoopLayout::name()
  std::string obstacles;  // obstacles_name()
  int balls = 0;
  int reachable = 0;  // balls the mouth can be put over with the body clear (from the truth)
  int collected = 0;
  int unreachable = 0;      // balls the robot gave up on (robot/collector_robot.hpp)
  double time_s = 0.0;      // simulated: when the last ball was collected; the limit when not
                            // all were (the robot gave up, seeing none, or ran out of time)
  double distance_m = 0.0;  // driven until then
  bool all = false;
  bool timed_out = false;        // not all collected, and the robot still at work at the limit
  bool never_overlapped = true;  // the net and the fence (checked on every tick's true pose)
  int stalls = 0;      // times the robot found itself stalled and freed itself (progress_recovery)
  int recoveries = 0;  // recovery behaviours it began (a back-up, a drive ahead)
  int contacts = 0;    // ticks (0.1 s) in which the net or the fence stopped the robot
  int dead_reckoned = 0;  // frame sets the cameras did not see the robot and it drove on its own
                          // estimate (robot/pose_tracker.hpp)
  int guarded = 0;        // commands the robot's local planner slowed, replaced or stopped
  double min_clearance_m = 0.0;  // the body's nearest approach to the net, the fence or an
                                 // obstacle (truth)
  int unloads = 0;               // times the basket was emptied at the unload point (truth)
};

/// How the robot reaches the service in a run: a link to `service`'s updates in `hub` that owns
/// whatever carries it (stopping the link stops that too).
using RobotConnector =
    std::function<std::unique_ptr<RobotLink>(CourtService& service, NavigationHub& hub)>;

/// The simulated collector of a run: its body's latency and slip, and the latency its controller
/// steers ahead by (robot/collector_robot.hpp).
struct LoopRobot {
  sim::RobotImperfections body;
  double steer_ahead_s = 0.0;
  std::optional<int> capacity;  // its basket's balls, if not the site's default (60)
};

/// One scene, one system, until every ball is collected or `max_time_s` of simulated time.
/// `record`: where the court's record goes (service/loop_truth.hpp), empty for nowhere; `mcap`:
/// how the run is recorded in MCAP (docs/recording.md), nullptr for not at all.
LoopRun run_loop(const LoopSystem& system, const LoopScene& scene, double max_time_s,
                 const RobotConnector& connect, const std::filesystem::path& record = {},
                 const LoopRobot& robot = {}, const RecordOptions* mcap = nullptr);

struct LoopEvalOptions {
  std::uint64_t seed = 1;
  // The default mix: 24 scenes, the five layouts in turn (loop_layouts), 10 to 120 balls spread
  // evenly over them (the scenes over the basket's 60 balls need an unload trip).
  int scenes = 24;
  int min_balls = 10, max_balls = 120;
  double max_time_s = 400.0;         // simulated, per run
  std::vector<std::string> systems;  // empty: all three
  std::vector<std::string> layouts;  // LoopLayout::name()s taken in turn; empty: all
  /// The obstacles of every scene; nullopt: the mix (loop_obstacles).
  std::optional<sim::ObstacleOptions> obstacles;
  std::filesystem::path record_dir;  // each run's record as <system>-<seed>.jsonl (empty: none)
  /// With record_dir: each run also recorded as <system>-<seed>.mcap, every update and the
  /// frames of every 10th frame set.
  bool record_mcap = false;
  LoopRobot robot;  // a perfect robot by default

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Every system on every scene; `progress` hears each run as it ends.
std::vector<LoopRun> run_loop_eval(const LoopEvalOptions& options, const RobotConnector& connect,
                                   const std::function<void(const LoopRun&)>& progress = {});

/// {"systems": {"<name>": {"collected_fraction", "time_s_mean", "distance_m_mean",
///  "time_ratio_to_ballsight", "runs": [...]}}, "scenes": [{"seed", "layout", "obstacles", "balls",
///  "reachable", "systems": {"<name>": {"collected", "unreachable", "time_s", "timed_out",
///  "contacts", "stalls", "recoveries", "min_clearance_m", "unloads"}}}]} (scenes in the order run)
nlohmann::json loop_eval_json(const std::vector<LoopRun>& runs);

}  // namespace ballsight::eval
