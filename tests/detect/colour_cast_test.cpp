// A warm lamp's cast read off the photo's whites, and the colour table corrected for it.
#include "ballsight/detect/colour_cast.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/ball_colours.hpp"

namespace ballsight {
namespace {

// A grey floor with white lines and a saturated patch, each channel scaled by `cast` (B, G, R),
// with sensor noise.
cv::Mat lined_floor(const cv::Vec3d& cast) {
  cv::Mat image(240, 320, CV_8UC3, cv::Scalar(110, 110, 110));
  for (int y = 20; y < 240; y += 40)
    cv::line(image, {0, y}, {319, y + 10}, cv::Scalar::all(215), 3);
  cv::rectangle(image, {200, 150}, {260, 200}, cv::Scalar(40, 200, 175), -1);
  cv::Mat noise(image.size(), CV_16SC3);
  cv::theRNG().state = 5;
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(3));
  cv::Mat lit;
  image.convertTo(lit, CV_32FC3);
  cv::multiply(lit, cv::Scalar(cast[0], cast[1], cast[2]), lit);
  cv::add(lit, noise, lit, cv::noArray(), CV_32FC3);
  lit.convertTo(image, CV_8UC3);
  return image;
}

TEST(ColourCast, GainsMakeAWarmLampsWhiteGrey) {
  const cv::Vec3d cast(0.8, 1.0, 1.12);
  const std::optional<cv::Vec3d> gains = warm_cast_gains(lined_floor(cast));
  ASSERT_TRUE(gains.has_value());
  // The white of the lines, corrected: grey within 2 %.
  const cv::Vec3d white(215 * cast[0] * (*gains)[0], 215 * cast[1] * (*gains)[1],
                        215 * cast[2] * (*gains)[2]);
  const double mean = (white[0] + white[1] + white[2]) / 3.0;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c] / mean, 1.0, 0.02) << "channel " << c;
}

TEST(ColourCast, DaylightAndClippedWhitesAreLeftAlone) {
  EXPECT_FALSE(warm_cast_gains(lined_floor({1.0, 1.0, 1.0})).has_value());
  EXPECT_FALSE(warm_cast_gains(lined_floor({1.1, 1.0, 0.95})).has_value());   // bluish
  EXPECT_FALSE(warm_cast_gains(lined_floor({0.97, 1.0, 1.03})).has_value());  // faintly warm
  EXPECT_FALSE(warm_cast_gains(cv::Mat(240, 320, CV_8UC3, cv::Scalar::all(0))).has_value());
  EXPECT_FALSE(warm_cast_gains(lined_floor({0.8, 1.0, 1.12}) * 0.2).has_value());  // too dark
  EXPECT_FALSE(warm_cast_gains(lined_floor({0.6, 1.0, 1.12})).has_value());  // sand, not a lamp
  cv::Mat clipped = lined_floor({0.8, 1.0, 1.12});
  clipped.setTo(cv::Scalar::all(255), clipped > 200);  // the lines' red and green burnt out
  EXPECT_FALSE(warm_cast_gains(clipped).has_value());
}

TEST(ColourCast, TheCorrectedTableClassifiesTheCorrectedColour) {
  const ColorClassTable table = ball_colour_table(default_ball_colours());
  const cv::Vec3d gains(1.2, 1.0, 0.85);
  const ColorClassTable corrected = corrected_for_cast(table, gains);
  int differing = 0;
  for (int b = 2; b < 256; b += 12)  // cell centres (4 levels a cell)
    for (int g = 2; g < 256; g += 12)
      for (int r = 2; r < 256; r += 12) {
        const cv::Vec3b p(static_cast<uchar>(b), static_cast<uchar>(g), static_cast<uchar>(r));
        const cv::Vec3b q(cv::saturate_cast<uchar>(b * gains[0]), cv::saturate_cast<uchar>(g),
                          cv::saturate_cast<uchar>(r * gains[2]));
        ASSERT_EQ(corrected.classify(p), table.classify(q)) << p << " -> " << q;
        differing += corrected.classify(p) != table.classify(p);
      }
  EXPECT_GT(differing, 0);  // the cast moves some colours into or out of the ball classes
}

TEST(ColourCast, AnImageThatIsNotColourIsAnError) {
  EXPECT_THROW(warm_cast_gains(cv::Mat(240, 320, CV_8UC1, cv::Scalar(200))), InputError);
  EXPECT_THROW(warm_cast_gains(cv::Mat()), InputError);
}

// A camera's frames: the table follows each frame's cast, and is the model's own in daylight.
TEST(ColourCast, TheTableFollowsTheFramesCast) {
  const ColorClassTable model = ball_colour_table(default_ball_colours());
  CastCorrectedTable table(model);
  const cv::Vec3b lamp_lit_line(172, 215, 241);  // a grey of 215 under (0.8, 1.0, 1.12)
  const cv::Mat warm = lined_floor({0.8, 1.0, 1.12});
  const ColorClassTable expected = corrected_for_cast(model, *warm_cast_gains(warm));
  for (int frame = 0; frame < 3; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const cv::Mat image = frame == 1 ? lined_floor({1.0, 1.0, 1.0}) : warm;
    const ColorClassTable& used = table.update(image);
    EXPECT_EQ(&used, &table.current());
    const ColorClassTable& truth = frame == 1 ? model : expected;
    EXPECT_EQ(used.classify(lamp_lit_line), truth.classify(lamp_lit_line));
    EXPECT_EQ(used.classify(cv::Vec3b(40, 200, 175)), truth.classify(cv::Vec3b(40, 200, 175)));
  }
  // The probe tells the two tables apart, and the model stays the model.
  EXPECT_NE(expected.classify(lamp_lit_line), model.classify(lamp_lit_line));
  EXPECT_EQ(table.model().classify(lamp_lit_line), model.classify(lamp_lit_line));
}

}  // namespace
}  // namespace ballsight
