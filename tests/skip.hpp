#pragma once
// A test that needs what a user's clone may lack (../shared/data, a Debian package's files) skips
// with a message there. In CI (CI=true) both are always present, so there the same test fails
// instead: a skip in CI would pass without testing anything.
//   if (!exists(dir)) BALLSIGHT_SKIP() << "no " << dir << " (../shared/data absent)";

#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

namespace ballsight::test {

inline bool in_ci() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string_view(ci) == "true";
}

}  // namespace ballsight::test

// GTEST_SKIP's own expansion, with the result chosen at run time.
#define BALLSIGHT_SKIP()                                                                         \
  return GTEST_MESSAGE_AT_(__FILE__, __LINE__,                                                   \
                           ::ballsight::test::in_ci() ? "CI=true, so this skip fails: " : "",    \
                           ::ballsight::test::in_ci() ? ::testing::TestPartResult::kFatalFailure \
                                                      : ::testing::TestPartResult::kSkip)
