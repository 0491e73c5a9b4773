#pragma once
// `ballsight serve --sim`: the navigation service on the built-in simulated court, in simulated
// time. Every vision tick the four corner cameras are rendered from the court's truth (fresh
// sensor noise each time, the robot where it really is, collected balls gone), ballsight's court
// pipeline turns the frames into a world model, the route is planned and the update published:
// the frames, not the truth, are what the service sees. Then the court advances one vision
// period: the simulated robot (`ballsight robot`) drives with the command it sent for that update
// (PUT /api/v1/sim/drive; the service waits for it, so simulated time runs as fast as the two
// programs allow, or at wall time with `realtime` or while no robot drives), its collector picks
// up the balls it passes over, the net and the fence stop it. With no robot driving, a ball
// reported collected is taken off the court by hand, as in the report's own test. The cameras'
// calibration is the simulator's (calibrating from rendered chessboards is `eval court`'s
// business). The court's record (`truth_out`, loop_truth.hpp) is the physical world: a
// service started again with `resume` continues the court from it (robot where it stood,
// collected balls gone, the clock on), as a real court outlives its service.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include "ballsight/service/court_service.hpp"
#include "ballsight/service/loop_truth.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/court_world.hpp"

namespace ballsight {

/// A camera that delivers no frames from one moment of simulated time until another (or for good).
struct CameraOutage {
  int camera = 0;  // index in the site's cameras
  double from_s = 0.0;
  double until_s = std::numeric_limits<double>::infinity();

  bool covers(double time_s) const { return time_s >= from_s && time_s < until_s; }
};

struct SimulatedServiceOptions {
  std::uint64_t seed = 1;
  std::optional<int> balls;     // tennis balls on the court; nullopt: the scenario's 20-60
  double cluster_share = 0.25;  // of them, in clusters of 2-4 touching balls
  sim::BallLayout layout = sim::BallLayout::scattered;  // where the others lie
  double vision_hz = 10.0;                              // frame sets per second of simulated time
  bool realtime = false;      // simulated time at wall time (else as fast as possible)
  double robot_wait_s = 1.0;  // for a driving robot's command, at most (wall)
  // Every tick waits, however long, for the robot's acknowledgement of the newest update (sent
  // after its command and its report of collected balls, which publishes an update of its own),
  // from the first update on: the run then never depends on wall time or the machine's load
  // (eval loop: same seed, same run).
  bool lockstep = false;
  std::filesystem::path truth_out;  // JSON lines, one per tick (empty: not written)
  bool resume = false;              // continue the court recorded in truth_out (when it exists)
  std::vector<CameraOutage> camera_outages;  // a camera may fail and come back, several times
  bool report_pipeline = false;              // the report's court pipeline instead of ballsight's
  PlannerOptions planner;
  sim::RobotImperfections robot;   // the simulated collector's latency and slip (its seed: seed's)
  std::optional<int> capacity;     // the basket's balls (site.yml's robot.capacity), if not 60
  sim::ObstacleOptions obstacles;  // people and bags on the court (none by default)
  std::function<void(sim::CourtScene&)> arrange;  // SimulatedCourtOptions::arrange

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class SimulatedCourtService : public CourtService {
 public:
  explicit SimulatedCourtService(const SimulatedServiceOptions& options);
  ~SimulatedCourtService() override;

  const Site& site() const override;
  void run(NavigationHub& hub, const std::atomic<bool>& stop) override;
  void republish(NavigationHub& hub) override;
  /// drive(), for the API's PUT /api/v1/sim/drive.
  SimulatedDrive simulated_drive() override;
  /// {"cameras": [{"name", "state": "simulated", "frames"}], "render_ms", "sim": {"time_s",
  /// "balls_left", "collected", "held", "robot", "driving", "blocked_ticks"}, and the figures of
  /// UpdatePublisher::health()}.
  nlohmann::json health() const override;

  /// The robot's command for the update `seq` (speed m/s, turn rate rad/s, counter-clockwise):
  /// it drives the next vision period. Returns {"collected": balls its collector took since its
  /// previous command (the collector's sensor), "held": balls in its basket, "time_s": simulated
  /// time, "odometry": the wheels' pose}. Any thread.
  nlohmann::json drive(std::uint64_t seq, double speed_mps, double turn_rate_rps);

  /// Where the robot stood when this service began (or resumed).
  Pose2D robot_start() const;
  /// The tennis balls as the scene began (loop_truth.hpp's scene record).
  const std::vector<SceneBall>& scene_balls() const;
  /// The people and bags on the court as it began (a walker where it started).
  const std::vector<sim::CourtObstacle>& scene_obstacles() const;
  /// What really happened, one tick per vision period; read it once run() has returned.
  const std::vector<sim::WorldTick>& history() const;

 protected:
  UpdatePublisher& publisher() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
