#pragma once
// `ballsight serve` in a child process for the CLI tests: its port from the line it prints, its
// stdout read through a pipe, and a kill at will (SIGTERM when the test is done with it).

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

extern char** environ;

namespace ballsight::test {

/// `ballsight serve ARGS...` in a child process.
class ServeProcess {
 public:
  /// `args` follow `ballsight serve`; they must include a --listen on 127.0.0.1.
  explicit ServeProcess(std::vector<std::string> args) {
    int fds[2];
    if (::pipe(fds) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    args.insert(args.begin(), {BALLSIGHT_CLI, "serve"});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, BALLSIGHT_CLI, &actions, nullptr, argv.data(), environ) != 0) pid_ = 0;
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    out_ = ::fdopen(fds[0], "r");
    char line[256] = {};
    if (pid_ > 0 && std::fgets(line, sizeof line, out_)) {
      const std::string first(line);
      const std::size_t at = first.find("127.0.0.1:");
      if (at != std::string::npos)
        port_ = static_cast<unsigned short>(std::stoi(first.substr(at + 10)));
    }
  }
  ~ServeProcess() { kill(SIGTERM); }

  unsigned short port() const { return port_; }
  void kill(int signal) {
    if (pid_ <= 0) return;
    ::kill(pid_, signal);
    ::waitpid(pid_, nullptr, 0);
    pid_ = 0;
    std::fclose(out_);
  }

 private:
  pid_t pid_ = 0;
  FILE* out_ = nullptr;
  unsigned short port_ = 0;
};

}  // namespace ballsight::test
