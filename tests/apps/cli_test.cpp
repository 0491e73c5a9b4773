#include <gtest/gtest.h>

#include "apps/run_cli.hpp"

namespace ballsight::test {
namespace {

TEST(Cli, HelpListsTheCommands) {
  const CliResult r = run_cli({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.stdout_text.find("sim"), std::string::npos) << r.stdout_text;
}

TEST(Cli, UnknownCommandFailsWithOneLine) {
  const CliResult r = run_cli({"frobnicate"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.stderr_text), 1) << r.stderr_text;
}

TEST(Cli, NoCommandFails) {
  const CliResult r = run_cli({});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.stderr_text), 1) << r.stderr_text;
}

}  // namespace
}  // namespace ballsight::test
