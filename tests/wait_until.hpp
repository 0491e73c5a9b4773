#pragma once
// A test waits for nothing without a deadline: `wait_until` checks a condition until it holds or
// the deadline passes, and the caller fails with what it waited for:
//   ASSERT_TRUE(test::wait_until([&] { return hub.latest_seq() >= 3; })) << "no third update";

#include <chrono>
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

}  // namespace ballsight::test
