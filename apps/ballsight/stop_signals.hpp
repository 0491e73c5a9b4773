#pragma once
// The long-running commands (serve, camera-node, court-node) stop on SIGINT or SIGTERM, or after
// --duration: the signals are blocked in every thread and taken by the waiting thread alone.

#include <signal.h>

#include <atomic>
#include <functional>

namespace ballsight::app {

class StopSignals {
 public:
  /// Blocks SIGINT and SIGTERM in this thread and every thread it starts from now on: make one
  /// before any thread starts (the HTTP server's, DDS's).
  StopSignals();

  /// Runs `work(stop)` on a thread of its own until a signal, `duration_s` (0: no limit) or the
  /// work's end; then sets `stop`, waits for the work and rethrows what it threw.
  void run_until_stopped(double duration_s,
                         const std::function<void(const std::atomic<bool>& stop)>& work) const;

 private:
  sigset_t signals_;
};

}  // namespace ballsight::app
