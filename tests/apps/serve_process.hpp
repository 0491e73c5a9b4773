#pragma once
// `ballsight serve` in a child process for the CLI tests (core/child_process.hpp): its port from
// the line it prints, its output in a log file of its own, and a kill at will (SIGTERM when the
// test is done with it).

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "ballsight/core/child_process.hpp"

namespace ballsight::test {

/// `ballsight serve ARGS...` in a child process.
class ServeProcess {
 public:
  /// `args` follow `ballsight serve`; they must include a --listen on 127.0.0.1.
  explicit ServeProcess(std::vector<std::string> args)
      : log_(fresh_log()), child_(BALLSIGHT_CLI, with_serve(std::move(args)), log_) {
    if (const auto line = child_.wait_for_line("127.0.0.1:", std::chrono::seconds(60))) {
      port_ = static_cast<unsigned short>(
          std::strtol(line->c_str() + line->find("127.0.0.1:") + 10, nullptr, 10));
    }
  }
  ~ServeProcess() {
    kill(SIGTERM);
    std::error_code ignored;
    std::filesystem::remove(log_, ignored);
  }
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  unsigned short port() const { return port_; }
  /// Sends `signal` and waits for the service to end.
  void kill(int signal) {
    child_.signal(signal);
    child_.wait(std::chrono::seconds(30));
  }

 private:
  static std::vector<std::string> with_serve(std::vector<std::string> args) {
    args.insert(args.begin(), "serve");
    return args;
  }
  static std::filesystem::path fresh_log() {
    static std::atomic<int> count{0};
    return std::filesystem::temp_directory_path() /
           ("ballsight_serve_" + std::to_string(::getpid()) + "_" + std::to_string(++count) +
            ".log");
  }

  std::filesystem::path log_;
  ChildProcess child_;
  unsigned short port_ = 0;
};

}  // namespace ballsight::test
