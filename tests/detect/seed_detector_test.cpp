#include "ballsight/detect/seed_detector.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "court_scene_support.hpp"

namespace ballsight {
namespace {

// The report's pipeline finds a ball of a few pixels and its contour centroid is close.
TEST(SeedDetector, FindsALargeBall) {
  const cv::Mat image = test::draw_discs({{{200.3, 150.6}, 6.0, test::kBallYellow}}, 2.0);
  const auto found = detect_seed(image, {});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].object, ObjectClass::ball);
  EXPECT_LT((found[0].center_px - Vec2(200.3, 150.6)).norm(), 0.5);
}

// Its 5x5 median filter erases balls of little more than a pixel in radius (most balls on a court
// seen from its corners): the baseline's main loss of recall.
TEST(SeedDetector, MedianFilterErasesSmallBalls) {
  const cv::Mat image = test::draw_discs({{{200.3, 150.6}, 1.4, test::kBallYellow}});
  EXPECT_TRUE(detect_seed(image, {}).empty());
  EXPECT_EQ(detect_seed_colour(image, SeedDetectorOptions{}.ball, 1, ObjectClass::ball).size(), 1u);
}

// A box chosen around one colour, moved to another's hue; S and V stay, the hue bounds clamp.
TEST(SeedDetector, HueBoxesMoveToAnotherColour) {
  const HsvRange box{{100, 120, 30}, {125, 255, 255}};
  const cv::Vec3b blue{220, 80, 30}, violet{230, 40, 140}, orange{20, 100, 255};
  EXPECT_EQ(opencv_hue(blue), 112);
  EXPECT_EQ(opencv_hue(violet), 136);
  const HsvRange moved = hue_moved(box, blue, violet);
  EXPECT_EQ(moved.min, (std::array<int, 3>{124, 120, 30}));
  EXPECT_EQ(moved.max, (std::array<int, 3>{149, 255, 255}));
  const HsvRange same = hue_moved(box, blue, blue);
  EXPECT_EQ(same.min, box.min);
  EXPECT_EQ(same.max, box.max);
  const HsvRange clamped = hue_moved(box, blue, orange);  // orange's hue is 10
  EXPECT_EQ(clamped.min[0], 0);
  EXPECT_EQ(clamped.max[0], 23);
  EXPECT_NO_THROW(clamped.validate("moved"));
}

TEST(SeedDetector, BadOptionsAreErrors) {
  SeedDetectorOptions options;
  options.median_kernel_px = 4;
  EXPECT_THROW(options.validate(), InputError);
  options = {};
  options.ball.max[0] = 200;
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace ballsight
