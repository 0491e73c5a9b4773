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
