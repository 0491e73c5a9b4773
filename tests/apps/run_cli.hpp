#pragma once
// Runs the built `ballsight` program with arguments and captures its exit status and output.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace ballsight::test {

struct CliResult {
  int exit_code = -1;  // -1 when the program was killed by a signal
  std::string stdout_text;
  std::string stderr_text;
};

/// Runs BALLSIGHT_CLI with `args` (each shell-quoted), capturing stdout and stderr.
inline CliResult run_cli(const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  const fs::path err_file =
      fs::temp_directory_path() / ("ballsight_cli_" + std::to_string(::getpid()) + ".err");
  std::string command = "'" BALLSIGHT_CLI "'";
  for (const std::string& a : args) {
    std::string quoted;
    for (char c : a) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    command += " '" + quoted + "'";
  }
  command += " 2>'" + err_file.string() + "'";
  CliResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.stdout_text.append(buffer.data(), n);
  }
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (FILE* err = std::fopen(err_file.c_str(), "r")) {
    while ((n = std::fread(buffer.data(), 1, buffer.size(), err)) > 0) {
      result.stderr_text.append(buffer.data(), n);
    }
    std::fclose(err);
  }
  fs::remove(err_file);
  return result;
}

/// Number of lines in `text` (a trailing newline does not start a new line).
inline int line_count(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += (c == '\n');
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines;
}

/// A bad input: exit status 2 and one line "ballsight: error: ..." on stderr containing `expected`.
inline void expect_one_line_error(const CliResult& r, const std::string& expected) {
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_EQ(line_count(r.stderr_text), 1) << r.stderr_text;
  EXPECT_EQ(r.stderr_text.rfind("ballsight: error: ", 0), 0u) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find(expected), std::string::npos) << r.stderr_text;
}

}  // namespace ballsight::test
