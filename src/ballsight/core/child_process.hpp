#pragma once
// A program run as a child process (posix_spawn), its output written to a log file: the demo
// starts the navigation service and the robot this way, as separate processes on one machine.

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ballsight {

/// Where this program's own executable is (/proc/self/exe).
std::filesystem::path own_executable();

class ChildProcess {
 public:
  /// Starts `program` with `args`; its stdout and stderr go to `log` (created or truncated).
  /// Throws InputError naming the program or the log when either cannot be started or opened.
  ChildProcess(const std::filesystem::path& program, const std::vector<std::string>& args,
               const std::filesystem::path& log);
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  /// Stops a child still running: SIGTERM, then SIGKILL when it has not ended within 5 s.
  ~ChildProcess();

  /// The first line of the log containing `text`, waiting for it up to `timeout`; nullopt when
  /// it did not come or the child ended first.
  std::optional<std::string> wait_for_line(const std::string& text,
                                           std::chrono::milliseconds timeout);
  /// The exit status (or 128 + signal) once the child has ended; nullopt while it runs.
  std::optional<int> exit_status();
  /// Waits for the child to end, up to `timeout`; its status, or nullopt when it still runs.
  std::optional<int> wait(std::chrono::milliseconds timeout);
  /// Sends `signal` to a running child.
  void signal(int signal) const;
  /// SIGTERM, wait up to `grace`, then SIGKILL; the status.
  int stop(std::chrono::milliseconds grace = std::chrono::seconds(5));

  pid_t pid() const { return pid_; }
  const std::filesystem::path& log() const { return log_; }
  std::string log_text() const;

 private:
  std::string program_;
  std::filesystem::path log_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

}  // namespace ballsight
