#include "ballsight/eval/wall_clock.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

TEST(WallClock, TimedMembersMoveToTheSamePathUnderOneKey) {
  const nlohmann::json doc = nlohmann::json::parse(R"({
    "seed": 3,
    "methods": {"a": {"recall": 0.5, "ms": 1.5, "by": {"12": {"ms": 2.5, "n": 1}}},
                "b": {"recall": 1.0}},
    "rows": [{"ms": 4.0}]
  })");
  const nlohmann::json out = with_wall_clock_apart(doc, {"ms"});
  EXPECT_EQ(out, nlohmann::json::parse(R"({
    "seed": 3,
    "methods": {"a": {"recall": 0.5, "by": {"12": {"n": 1}}}, "b": {"recall": 1.0}},
    "rows": [{"ms": 4.0}],
    "wall_clock": {"methods": {"a": {"ms": 1.5, "by": {"12": {"ms": 2.5}}}}}
  })"));
}

TEST(WallClock, NothingTimedLeavesAnEmptyWallClock) {
  const nlohmann::json out = with_wall_clock_apart({{"systems", {{"a", 1}}}}, {});
  EXPECT_EQ(out["wall_clock"], nlohmann::json::object());
  EXPECT_EQ(out["systems"]["a"], 1);
}

}  // namespace
}  // namespace ballsight
