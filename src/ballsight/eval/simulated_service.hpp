#pragma once
// `ballsight serve --sim`: the navigation service on the built-in simulated court. The four
// corner cameras are rendered over and over (fresh sensor noise each time; balls the robot
// reports collected vanish from the court), ballsight's court pipeline turns every frame set into
// a world model, the route is planned and the update published: the frames, not the truth, are
// what the service sees. The cameras' calibration is the simulator's (calibrating from rendered
// chessboards is `eval court`'s business).

#include <cstdint>
#include <memory>

#include "ballsight/net/court_service.hpp"

namespace ballsight {

struct SimulatedServiceOptions {
  std::uint64_t seed = 1;
  double max_rate_hz = 10.0;  // frame sets per second at most
  PlannerOptions planner;

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
  /// {"cameras": [{"name", "state": "simulated", "frames"}], "render_ms", and the figures of
  /// UpdatePublisher::health()}.
  nlohmann::json health() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
