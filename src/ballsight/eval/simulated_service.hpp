#pragma once
// `ballsight serve --sim`: the navigation service on the built-in simulated court. The four
// corner cameras are rendered over and over (fresh sensor noise each time; balls the robot
// reports collected vanish from the court), ballsight's court pipeline turns every frame set into
// a world model, the route is planned and the update published: the frames, not the truth, are
// what the service sees. The cameras' calibration is the simulator's (calibrating from rendered
// chessboards is `eval court`'s business).

#include <atomic>
#include <cstdint>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ballsight/net/navigation_hub.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct SimulatedServiceOptions {
  std::uint64_t seed = 1;
  double max_rate_hz = 10.0;  // frame sets per second at most
  PlannerOptions planner;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class SimulatedCourtService {
 public:
  explicit SimulatedCourtService(const SimulatedServiceOptions& options);
  ~SimulatedCourtService();

  const Site& site() const;
  std::vector<std::string> camera_names() const;

  /// Captures, plans and publishes into `hub` until `stop` is set.
  void run(NavigationHub& hub, const std::atomic<bool>& stop);

  /// {"cameras": [{"name", "state", "frames"}], "frame_sets", "updates_published",
  ///  "render_ms", "pipeline_ms", "plan_ms", "frame_sets_per_s", "last_error"}.
  nlohmann::json health() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
