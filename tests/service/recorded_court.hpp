#pragma once
// A small simulated court, and a run of it recorded (service/run_recorder.hpp): what the
// recorder's and the replay's tests record.

#include <gtest/gtest.h>

#include <functional>
#include <optional>

#include "ballsight/service/run_recorder.hpp"
#include "service/running_service.hpp"
#include "wait_until.hpp"

namespace ballsight::test {

inline SimulatedServiceOptions small_court() {
  SimulatedServiceOptions options;
  options.seed = 3;
  options.balls = 6;
  options.vision_hz = 20.0;
  return options;
}

/// Runs `court` with a recorder until `updates` updates are published (`during` runs once,
/// after the first update, on the test's thread); the final counts.
inline RecorderCounts record_run(const RecordOptions& options, std::uint64_t updates,
                                 const SimulatedServiceOptions& court = small_court(),
                                 const std::function<void(RunningService&)>& during = {}) {
  std::optional<RunRecorder> recorder;
  RunningService running(court, [&](SimulatedCourtService& service, NavigationHub& hub) {
    recorder.emplace(hub, service, options);
  });
  if (during) {
    EXPECT_TRUE(wait_until([&] { return running.hub.latest_seq() >= 1; }));
    during(running);
  }
  EXPECT_TRUE(wait_until([&] { return running.hub.latest_seq() >= updates; }))
      << "the service published " << running.hub.latest_seq() << " updates";
  running.stop_and_join();
  const RecorderCounts counts = recorder->finish();
  EXPECT_EQ(counts.updates + counts.dropped, running.hub.latest_seq());
  EXPECT_EQ(counts.error, "");
  return counts;
}

}  // namespace ballsight::test
