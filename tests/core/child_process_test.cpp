#include "ballsight/core/child_process.hpp"

#include <gtest/gtest.h>

#include <csignal>

#include "ballsight/core/error.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

using namespace std::chrono_literals;

TEST(ChildProcess, ItsOutputGoesToTheLogAndItStopsWhenTold) {
  const test::TempDir dir;
  ChildProcess child("/bin/sh", {"-c", "echo listening on 42; exec sleep 30"}, dir / "child.log");
  const std::optional<std::string> line = child.wait_for_line("listening", 10s);
  ASSERT_TRUE(line);
  EXPECT_EQ(*line, "listening on 42");
  EXPECT_FALSE(child.exit_status());
  EXPECT_EQ(child.stop(), 128 + SIGTERM);
  EXPECT_EQ(child.exit_status(), 128 + SIGTERM);
}

TEST(ChildProcess, AnEndedChildGivesItsStatusAndNoLine) {
  const test::TempDir dir;
  ChildProcess child("/bin/sh", {"-c", "echo bye >&2; exit 3"}, dir / "child.log");
  EXPECT_EQ(child.wait(10s), 3);
  EXPECT_FALSE(child.wait_for_line("never", 1s));
  EXPECT_EQ(child.log_text(), "bye\n");
  EXPECT_THROW(ChildProcess("/no/such/program", {}, dir / "x.log"), InputError);
  EXPECT_THROW(ChildProcess("/bin/sh", {}, dir / "no" / "such" / "dir.log"), InputError);
  EXPECT_FALSE(own_executable().empty());
}

}  // namespace
}  // namespace ballsight
