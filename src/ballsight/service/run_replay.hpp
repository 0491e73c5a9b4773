#pragma once
// `ballsight eval replay`: a recorded run's frames through this build's pipeline and planner, on
// the service's own path (UpdatePublisher: the pipeline, the plan with the reports the recorded
// update was planned with, warm-started from the previous route), compared update by update
// with what was recorded: balls added, lost and moved, the robot's pose, the route. With the
// build that recorded it and lossless frames (--record-frames png) nothing differs; after a
// change the differences are what the change did (docs/recording.md, "Replay").

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/service/court_service.hpp"
#include "ballsight/service/recorded_run.hpp"

namespace ballsight {

/// A ball farther than this from where it was recorded has moved.
constexpr double kReplayMovedM = 0.02;

struct ReplayOptions {
  /// Plan with this planner instead of the recorded one (what another planner would have done).
  std::optional<PlannerKind> planner;
};

/// One recorded update against its replay.
struct ReplayedUpdate {
  std::uint64_t seq = 0;
  /// Why it could not be replayed ("" when it was): its frames were not recorded.
  std::string not_replayed;
  int balls_recorded = 0, balls_replayed = 0;
  int balls_added = 0;            // replayed with no recorded ball within reach (kMatchM)
  int balls_lost = 0;             // recorded with no replayed ball within reach
  int balls_moved = 0;            // paired, farther apart than kReplayMovedM
  double ball_shift_max_m = 0.0;  // of the paired balls
  /// "same", "added" (seen by the replay only), "lost" (by the recording only) or "none".
  std::string robot = "none";
  double robot_shift_m = 0.0, robot_turn_deg = 0.0;  // when both saw it
  bool route_changed = false;  // another order, or a waypoint moved beyond kReplayMovedM

  /// Whether anything above differs beyond its tolerance (a robot pose: 2 cm or 1 degree).
  bool differs() const;
};

struct ReplayReport {
  std::string file;
  std::string frames;  // the recording's frame encoding
  std::vector<ReplayedUpdate> updates;
};

/// Feeds recorded updates to a service's publisher as the service fed it: a new frame set's
/// frames through the pipeline, a re-plan of the same world as a re-plan, each planned with the
/// reports the recorded update was planned with, and the planner switched where the recording
/// switched it (CourtService::set_planner: from scratch). `eval replay` and `serve --replay`.
class UpdateReplayer {
 public:
  UpdateReplayer(UpdatePublisher& publisher, const PlannerOptions& planner,
                 const ReplayOptions& options);
  /// Publishes the replay of `recorded` into `hub`: its seq, or 0 when it could not be replayed
  /// (`why` says why: its frames were not recorded, ...).
  std::uint64_t feed(const RecordedUpdate& recorded, NavigationHub& hub, std::string& why);

 private:
  UpdatePublisher& publisher_;
  PlannerOptions planner_;
  bool fixed_planner_;
  bool world_ = false;  // a frame set went through the pipeline
};

/// Replays `run` (see above).
ReplayReport replay_run(const RecordedRun& run, const ReplayOptions& options = {});

/// {"file", "frames", "updates", "replayed", "not_replayed", "differing", "balls_added",
/// "balls_lost", "balls_moved", "ball_shift_max_m", "robot_shift_max_m", "robot_turn_max_deg",
/// "routes_changed", "per_update": [...]} (per_update: the updates that differ or were not
/// replayed, all of them with `all`).
nlohmann::json replay_json(const ReplayReport& report, bool all = false);

}  // namespace ballsight
