#include "ballsight/detect/mirror_rim.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace ballsight {
namespace {

// A bright disc of known centre on a dark housing, cut by the image's top and bottom (as the
// simulated and many real omni frames are), with a dark robot body in the middle.
cv::Mat disc_image(const Vec2& center, double radius) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(10, 12, 8));
  constexpr int kShift = 8;  // sub-pixel drawing
  const cv::Point c(static_cast<int>(std::lround(center.x() * (1 << kShift))),
                    static_cast<int>(std::lround(center.y() * (1 << kShift))));
  cv::circle(image, c, static_cast<int>(std::lround(radius * (1 << kShift))),
             cv::Scalar(60, 150, 70), cv::FILLED, cv::LINE_AA, kShift);
  cv::circle(image, c, 30 << kShift, cv::Scalar(25, 25, 25), cv::FILLED, cv::LINE_AA, kShift);
  return image;
}

TEST(MirrorRim, FindsACutDiscsCentre) {
  for (const Vec2& center : {Vec2(319.5, 239.5), Vec2(326.25, 233.75), Vec2(300.0, 250.0)}) {
    const std::optional<MirrorRim> rim = find_mirror_rim(disc_image(center, 255.0));
    ASSERT_TRUE(rim.has_value()) << center.transpose();
    EXPECT_NEAR(rim->center_px.x(), center.x(), 0.5);
    EXPECT_NEAR(rim->center_px.y(), center.y(), 0.5);
    EXPECT_NEAR(rim->radius_px, 255.0, 1.0);
    EXPECT_LT(rim->coverage, 0.9);  // cut by the image's border
  }
}

TEST(MirrorRim, NoRimInViewIsNoSuggestion) {
  EXPECT_FALSE(find_mirror_rim(cv::Mat(480, 640, CV_8UC3, cv::Scalar(0, 0, 0))).has_value());
  // A mirror that fills the whole image: its edge is the image's border.
  EXPECT_FALSE(find_mirror_rim(disc_image(Vec2(319.5, 239.5), 500.0)).has_value());
  // A square is not round.
  cv::Mat square(480, 640, CV_8UC3, cv::Scalar(0, 0, 0));
  cv::rectangle(square, cv::Rect(170, 90, 300, 300), cv::Scalar(200, 200, 200), cv::FILLED);
  EXPECT_FALSE(find_mirror_rim(square).has_value());
  EXPECT_FALSE(find_mirror_rim(cv::Mat()).has_value());
}

}  // namespace
}  // namespace ballsight
