#include "ballsight/world/net_panel.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

TEST(NetPanel, TopCordFallsFromThePostsToTheCentre) {
  const NetPanel net;
  EXPECT_DOUBLE_EQ(net.top_m(0.0), 0.914);
  EXPECT_DOUBLE_EQ(net.top_m(net.half_length_m), 1.07);
  EXPECT_DOUBLE_EQ(net.top_m(-net.half_length_m), 1.07);
}

TEST(NetPanel, HidesWhatIsLowBehindItFromTheOtherSide) {
  const NetPanel net;
  const Vec3 eye(-18.0, -9.0, 5.0);  // a camera pole at a corner
  const Vec3 near_net(2.0, -1.0, 0.0335), far(14.0, 5.0, 0.0335);
  EXPECT_TRUE(net.hides(eye, near_net));  // the line of sight crosses x = 0 at ~0.5 m height
  EXPECT_FALSE(net.hides(eye, far));      // ... at ~2 m: over the net
  EXPECT_FALSE(net.hides(eye, Vec3(-2.0, -1.0, 0.0335)));                  // the same side
  EXPECT_FALSE(net.hides(Vec3(-18.0, 0.0, 5.0), Vec3(2.0, 8.0, 0.0335)));  // past the post
}

}  // namespace
}  // namespace ballsight
