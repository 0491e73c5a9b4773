#pragma once
// A simulated court service running on a thread of its own until stop_and_join() or the end of
// the test (so that a failed ASSERT ends it cleanly). `before_start` runs once the service and
// its hub are built and before the first frame set (to attach a listener that must see them all).

#include <atomic>
#include <functional>
#include <thread>

#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/service/simulated_service.hpp"

namespace ballsight::test {

struct RunningService {
  explicit RunningService(
      const SimulatedServiceOptions& options,
      const std::function<void(SimulatedCourtService&, NavigationHub&)>& before_start = {})
      : service(options) {
    if (before_start) before_start(service, hub);
    runner = std::thread([this] { service.run(hub, stop); });
  }
  ~RunningService() { stop_and_join(); }

  void stop_and_join() {
    stop = true;
    if (runner.joinable()) runner.join();
  }
  double sim_time() const { return service.health()["sim"]["time_s"].get<double>(); }

  SimulatedCourtService service;
  NavigationHub hub;
  std::atomic<bool> stop{false};
  std::thread runner;
};

}  // namespace ballsight::test
