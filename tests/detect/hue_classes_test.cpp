#include "ballsight/detect/hue_classes.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

TEST(HueClasses, HueOfPrimaryAndCourtColours) {
  EXPECT_NEAR(hue_deg({0, 0, 255}), 0.0, 1e-9);
  EXPECT_NEAR(hue_deg({0, 255, 0}), 120.0, 1e-9);
  EXPECT_NEAR(hue_deg({255, 0, 0}), 240.0, 1e-9);
  EXPECT_NEAR(hue_deg({45, 250, 225}), 67.3, 0.1);   // tennis ball
  EXPECT_NEAR(hue_deg({180, 80, 255}), 325.7, 0.1);  // pink marker
}

// A band keeps its hue when the light scales the colour, and one with min > max wraps through 0.
TEST(HueClasses, BandsAreLightInvariantAndWrap) {
  const HueBand yellow{45.0, 85.0, 30.0};
  for (double light : {0.3, 0.6, 1.0})
    EXPECT_TRUE(yellow.contains(cv::Vec3b(cv::saturate_cast<uchar>(45 * light),
                                          cv::saturate_cast<uchar>(250 * light),
                                          cv::saturate_cast<uchar>(225 * light))));
  EXPECT_FALSE(yellow.contains({88, 128, 70}));    // court green
  EXPECT_FALSE(yellow.contains({128, 134, 138}));  // grey: too little chroma
  const HueBand red{340.0, 20.0, 30.0};
  EXPECT_TRUE(red.contains({20, 20, 200}));
  EXPECT_TRUE(red.contains({60, 10, 200}));  // hue ~345
  EXPECT_FALSE(red.contains({20, 200, 20}));
}

TEST(HueClasses, TableAgreesWithTheBandsAwayFromBoundaries) {
  const HueBand yellow{45.0, 85.0, 30.0};
  const ColorClassTable table = hue_class_table({{1, yellow}});
  EXPECT_EQ(table.classify({45, 250, 225}), 1);
  EXPECT_EQ(table.classify({88, 128, 70}), 0);
}

}  // namespace
}  // namespace ballsight
