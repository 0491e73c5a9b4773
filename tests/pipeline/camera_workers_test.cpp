#include "ballsight/pipeline/camera_workers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>

#include "wait_until.hpp"

namespace ballsight {
namespace {

// Each test's rounds run under a deadline: a round that never ends fails the program, not ctest's
// timeout.
TEST(CameraWorkers, EveryJobRunsOnItsOwnLongLivedThreadRoundAfterRound) {
  const test::Deadline deadline("50 rounds of four camera workers");
  CameraWorkers workers(4);
  std::vector<std::thread::id> first(4), later(4);
  std::vector<int> runs(4, 0);
  for (int round = 0; round < 50; ++round) {
    std::vector<std::thread::id>& ids = round == 0 ? first : later;
    std::vector<std::function<void()>> jobs(4);
    for (std::size_t k = 0; k < 4; ++k) {
      if (round % 3 == 1 && k == 2) continue;  // a camera without a frame: no job
      jobs[k] = [&, k] {
        ids[k] = std::this_thread::get_id();
        ++runs[k];
      };
    }
    workers.run(jobs);
  }
  EXPECT_EQ(runs, (std::vector<int>{50, 50, 33, 50}));
  EXPECT_EQ(std::set<std::thread::id>(first.begin(), first.end()).size(), 4u);
  EXPECT_EQ(first, later);  // the same four threads every round
  EXPECT_EQ(std::count(first.begin(), first.end(), std::this_thread::get_id()), 0);
}

TEST(CameraWorkers, AJobsExceptionReachesTheCallerAndTheWorkersGoOn) {
  const test::Deadline deadline("two rounds of two camera workers, one failing");
  CameraWorkers workers(2);
  int ran = 0;
  EXPECT_THROW(workers.run({[] { throw std::runtime_error("camera 0 failed"); }, [&] { ++ran; }}),
               std::runtime_error);
  EXPECT_EQ(ran, 1);  // the other camera's job still ran to its end
  workers.run({[&] { ++ran; }, [&] { ++ran; }});
  EXPECT_EQ(ran, 3);
}

TEST(CameraWorkers, CallsFromSeveralThreadsTakeTurns) {
  const test::Deadline deadline("100 rounds from four callers");
  CameraWorkers workers(2);
  std::atomic<int> total{0};
  std::vector<std::thread> callers;
  for (int c = 0; c < 4; ++c) {
    callers.emplace_back([&] {
      for (int r = 0; r < 25; ++r) workers.run({[&] { ++total; }, [&] { ++total; }});
    });
  }
  for (std::thread& t : callers) t.join();
  EXPECT_EQ(total, 200);
}

}  // namespace
}  // namespace ballsight
