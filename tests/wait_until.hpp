#pragma once
// A test waits for nothing without a deadline: `wait_until` checks a condition until it holds or
// the deadline passes, and the caller fails with what it waited for:
//   ASSERT_TRUE(test::wait_until([&] { return hub.latest_seq() >= 3; })) << "no third update";
// A call that blocks (and cannot be asked whether it is done) runs under a `Deadline`, which ends
// the test program with a message when the call has not returned in time:
//   { const test::Deadline deadline("a round of the camera workers"); workers.run(jobs); }

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

namespace ballsight::test {

/// Calls `done` every `every` until it returns true (true) or `deadline` has passed (false).
template <class Done>
bool wait_until(Done&& done, std::chrono::milliseconds deadline = std::chrono::seconds(60),
                std::chrono::milliseconds every = std::chrono::milliseconds(5)) {
  const auto until = std::chrono::steady_clock::now() + deadline;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(every);
  }
  return true;
}

/// While it lives, a watchdog: when `deadline` passes first, it says `what` did not finish on
/// stderr and ends the program (exit code 1; a hung call cannot be failed any other way).
class Deadline {
 public:
  explicit Deadline(std::string what, std::chrono::milliseconds deadline = std::chrono::seconds(60))
      : watchdog_([this, what = std::move(what), deadline] {
          std::unique_lock lock(mutex_);
          if (!ended_.wait_for(lock, deadline, [this] { return done_; })) {
            std::fprintf(stderr, "deadline passed: %s did not finish within %lld ms\n",
                         what.c_str(), static_cast<long long>(deadline.count()));
            std::_Exit(1);
          }
        }) {}
  ~Deadline() {
    {
      const std::lock_guard lock(mutex_);
      done_ = true;
    }
    ended_.notify_one();
    watchdog_.join();
  }
  Deadline(const Deadline&) = delete;
  Deadline& operator=(const Deadline&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable ended_;
  bool done_ = false;
  std::thread watchdog_;  // last: it starts once the rest is there
};

}  // namespace ballsight::test
