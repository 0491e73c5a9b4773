#include "stop_signals.hpp"

#include <chrono>
#include <exception>
#include <thread>

namespace ballsight::app {

StopSignals::StopSignals() {
  sigemptyset(&signals_);
  sigaddset(&signals_, SIGINT);
  sigaddset(&signals_, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals_, nullptr);
}

void StopSignals::run_until_stopped(
    double duration_s, const std::function<void(const std::atomic<bool>& stop)>& work) const {
  using Clock = std::chrono::steady_clock;
  std::atomic<bool> stop{false}, ended{false};
  std::exception_ptr failure;  // the work's, ends the command with its message
  std::thread thread([&] {
    try {
      work(stop);
    } catch (...) {
      failure = std::current_exception();
    }
    ended = true;
  });
  const auto started = Clock::now();
  const timespec tick{0, 100'000'000};
  while (!ended && sigtimedwait(&signals_, nullptr, &tick) <= 0) {
    if (duration_s > 0.0 &&
        std::chrono::duration<double>(Clock::now() - started).count() >= duration_s)
      break;
  }
  stop = true;
  thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace ballsight::app
