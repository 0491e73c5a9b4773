// ballsight's ball detector for photos without a camera model, on drawn scenes whose balls are
// known exactly: sizes from 2 to 150 px, touching balls, balls cut by the border, shaded balls,
// and things of a ball's colour that are not balls.
#include "ballsight/detect/photo_balls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

struct DrawnBall {
  Vec2 center;
  double radius;
};

// A blue-grey hard court (or a floor of colour `bgr`) with pixel noise.
cv::Mat court(cv::Size size, unsigned seed = 1, const cv::Scalar& bgr = cv::Scalar(150, 120, 95)) {
  cv::Mat image(size, CV_8UC3, bgr);
  cv::Mat noise(size, CV_8UC3);
  cv::theRNG().state = seed;
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(4));
  cv::add(image, noise, image, cv::noArray(), CV_8UC3);
  return image;
}

// An optic-yellow ball lit from above: its lower part in its own shade, antialiased.
void draw_ball(cv::Mat& image, const DrawnBall& ball) {
  constexpr int kShift = 4;
  const cv::Point c(static_cast<int>(std::lround(ball.center.x() * 16)),
                    static_cast<int>(std::lround(ball.center.y() * 16)));
  const int r = static_cast<int>(std::lround(ball.radius * 16));
  cv::circle(image, c, r, cv::Scalar(40, 200, 175), -1, cv::LINE_AA, kShift);
  const cv::Point lit(c.x, c.y - r / 4);
  cv::circle(image, lit, r * 3 / 4, cv::Scalar(45, 245, 220), -1, cv::LINE_AA, kShift);
}

// The detection nearest `ball`, or nullptr when none is within its radius.
const PhotoBall* nearest(const std::vector<PhotoBall>& found, const DrawnBall& ball) {
  const PhotoBall* best = nullptr;
  for (const PhotoBall& b : found)
    if ((b.center_px - ball.center).norm() < ball.radius &&
        (!best || (b.center_px - ball.center).norm() < (best->center_px - ball.center).norm()))
      best = &b;
  return best;
}

// Radii within 15 % and `radius_slack_px`.
void expect_found(const std::vector<PhotoBall>& found, const std::vector<DrawnBall>& balls,
                  double radius_slack_px = 0.6) {
  EXPECT_EQ(found.size(), balls.size());
  for (const DrawnBall& ball : balls) {
    const PhotoBall* b = nearest(found, ball);
    ASSERT_NE(b, nullptr) << "ball at (" << ball.center.transpose() << ") r " << ball.radius;
    EXPECT_LE((b->center_px - ball.center).norm(), 0.15 * ball.radius + 0.3) << "r " << ball.radius;
    EXPECT_NEAR(b->radius_px, ball.radius, 0.15 * ball.radius + radius_slack_px)
        << "r " << ball.radius;
    EXPECT_GT(b->score, 0.5);
  }
}

// The balls drawn on a court of `size` (and colour `floor`) are found.
void expect_found_when_drawn(cv::Size size, const std::vector<DrawnBall>& balls,
                             const cv::Scalar& floor = {150, 120, 95}) {
  cv::Mat image = court(size, 1, floor);
  for (const DrawnBall& b : balls) draw_ball(image, b);
  PhotoBallDetector detector;
  expect_found(detector.detect(image), balls);
}

TEST(PhotoBalls, FindsSingleBallsFromTwoTo150Pixels) {
  for (const double r : {2.0, 3.0, 5.0, 10.0, 30.0, 80.0, 150.0}) {
    const auto side = static_cast<int>(2 * r + 60);
    expect_found_when_drawn({side, side}, {{Vec2(side / 2.0 + 0.3, side / 2.0 - 0.2), r}});
  }
}

TEST(PhotoBalls, SeparatesTouchingBalls) {
  expect_found_when_drawn({400, 200}, {{Vec2(100, 100), 30},
                                       {Vec2(160, 100), 30},
                                       {Vec2(300, 120), 40},
                                       {Vec2(300 + 40 + 15, 120 - 10), 15}});
}

// Far from a court camera the balls of a clump (here a row of four, and a pair) are a few pixels
// each: every one is found, though each has the others of its colour close around (they are not
// weeds: the clump narrows between its balls; a painted line does not,
// IgnoresALineAndFoliageOfABallsColour).
TEST(PhotoBalls, FindsEveryBallOfAClumpOfSmallBalls) {
  const std::vector<DrawnBall> balls{{Vec2(40.3, 60.2), 3.5},  {Vec2(47.7, 59.6), 3.5},
                                     {Vec2(55.0, 61.0), 3.5},  {Vec2(62.4, 60.4), 3.5},
                                     {Vec2(140.0, 60.0), 5.0}, {Vec2(149.5, 60.5), 5.0}};
  expect_found_when_drawn({200, 120}, balls);
}

// Balls lie in groups: small balls apart from each other but a few radii away each hold the
// others in the wide ring their isolation is judged by; a ball found beside them is no weed.
TEST(PhotoBalls, FindsSmallBallsLyingAFewRadiiApart) {
  const std::vector<DrawnBall> balls{{Vec2(40.3, 60.2), 3.5},  {Vec2(52.1, 57.4), 3.5},
                                     {Vec2(47.6, 70.8), 3.5},  {Vec2(140.0, 60.0), 2.5},
                                     {Vec2(148.2, 64.5), 2.5}, {Vec2(150.0, 52.0), 5.0}};
  expect_found_when_drawn({200, 120}, balls);
}

// A floor of a ball's colours: a wooden hall floor (hue 33 deg, in the yellow's and the orange's
// growth bands) and a red court (the orange's seed colour) grow into one blob with every ball on
// it. The floor's colours are no ball colours in that photo, and the balls on it are found.
TEST(PhotoBalls, FindsBallsOnAFloorOfABallsColour) {
  const std::vector<DrawnBall> balls{{Vec2(60.3, 60.2), 3.5},
                                     {Vec2(100.2, 190.7), 6},
                                     {Vec2(160, 110), 12},
                                     {Vec2(250.5, 170.5), 30}};
  for (const cv::Scalar& floor : {cv::Scalar(100, 150, 195), cv::Scalar(55, 65, 160)}) {
    SCOPED_TRACE("floor BGR " + std::to_string(floor[0]) + ", " + std::to_string(floor[1]) + ", " +
                 std::to_string(floor[2]));
    cv::Mat image = court({320, 240}, 1, floor);
    for (const DrawnBall& b : balls) draw_ball(image, b);
    PhotoBallDetector detector;
    expect_found(detector.detect(image), balls);
  }
}

// A dark court of the balls' own hue (hue 68 deg, saturation 0.45, value 45-135, as a stock
// photo's indoor green court lit from one side) grows into one blob with the balls: they are found
// by the contrast split, brighter and more saturated than the court, and not without it.
TEST(PhotoBalls, FindsBallsOnACourtOfTheirOwnHueByTheirContrast) {
  const std::vector<DrawnBall> balls{{Vec2(40.3, 50.2), 6},   {Vec2(120.2, 60.7), 7},
                                     {Vec2(210, 45), 8},      {Vec2(60.5, 170.5), 7.5},
                                     {Vec2(150.5, 180.5), 6}, {Vec2(260.5, 160.5), 8}};
  // Lit from one side: the court's value from 45 to 135 across the photo.
  cv::Mat image = court({320, 240}, 1, cv::Scalar(50, 90, 85));
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x)
      image.at<cv::Vec3b>(y, x) *= 0.5 + static_cast<double>(x) / image.cols;
  for (const DrawnBall& b : balls) draw_ball(image, b);
  PhotoBallDetector detector;
  expect_found(detector.detect(image), balls);
  PhotoBallOptions no_split;
  no_split.split.min_contrast = 255.0;
  EXPECT_LT(PhotoBallDetector(no_split).detect(image).size(), balls.size() / 2);
}

// A wooden floor with a patch in a shadow (a post's, say) of under 2 % of the photo: once the
// floor's colours are taken out, the patch's darker wood still grows into one blob with the balls
// lying in it; it is floor too, and its balls are found.
TEST(PhotoBalls, FindsBallsInAShadowOnAFloorOfABallsColour) {
  cv::Mat image = court({640, 480}, 1, cv::Scalar(100, 150, 195));
  const cv::Rect shadow(300, 200, 120, 40);
  const std::vector<DrawnBall> balls{
      {Vec2(330.3, 214.2), 3.0}, {Vec2(390.6, 223.7), 3.5}, {Vec2(40.5, 40.5), 4.0}};
  for (const DrawnBall& b : balls) draw_ball(image, b);
  cv::Mat shaded = image(shadow);
  shaded *= 0.5;
  PhotoBallDetector detector;
  expect_found(detector.detect(image), balls);
}

// A warm-tinted concrete floor (hue 45 deg, saturation 0.19) in white light (a white wall shows
// it: no cast is corrected): the camera's noise pushes about one pixel in five across the
// yellow's growth band, into the wide ring of every small ball. Those pixels are the smooth floor
// the balls lie on, not a field of leaves. (A ball's antialiased rim, half ball and half floor, is
// of a growth colour here: its blob and radius take in a pixel more than on a blue court.)
// Without the wall nothing white is in view: the floor's own colour is read as a lamp's cast
// and corrected, and the balls are found as well.
TEST(PhotoBalls, FindsSmallBallsOnASmoothFloorOfTheirHueFamily) {
  const std::vector<DrawnBall> balls{{Vec2(60.3, 60.2), 2.5},
                                     {Vec2(150.2, 90.7), 3.0},
                                     {Vec2(250.5, 170.5), 3.5},
                                     {Vec2(100.5, 180.5), 6.0}};
  for (const bool wall : {true, false}) {
    SCOPED_TRACE(wall ? "a white wall in view" : "no white in view");
    cv::Mat image = court({320, 240}, 1, cv::Scalar(113, 133, 140));
    if (wall) image(cv::Rect(0, 0, 320, 10)).setTo(cv::Scalar::all(235));
    for (const DrawnBall& b : balls) draw_ball(image, b);
    EXPECT_EQ(warm_cast_gains(image).has_value(), !wall);
    PhotoBallDetector detector;
    expect_found(detector.detect(image), balls, 1.2);
  }
}

// A small leaf of a ball's colour in leaf litter (dull yellow-green leaves of a growth colour,
// dark gaps between them) on the court: the litter around it is rough, so the leaf does not
// stand apart and is no ball, while a ball of its size on the bare court beside it is one.
TEST(PhotoBalls, IgnoresASmallLeafInLeafLitter) {
  cv::Mat image = court({300, 150});
  std::mt19937 random(9);
  std::uniform_int_distribution<int> x(20, 130), y(20, 130);
  for (int i = 0; i < 400; ++i) {
    const cv::Point at(x(random), y(random));
    if ((Vec2(at.x, at.y) - Vec2(75, 75)).norm() > 5.0)
      cv::circle(image, at, 1, i % 3 == 0 ? cv::Scalar(30, 45, 50) : cv::Scalar(85, 125, 120), -1);
  }
  draw_ball(image, {Vec2(75, 75), 2.5});  // the leaf
  const DrawnBall ball{Vec2(225, 75), 2.5};
  draw_ball(image, ball);
  PhotoBallDetector detector;
  expect_found(detector.detect(image), {ball});
}

// The far orange's washed-out colour seeds far balls only: a disc of it 3 px in radius is a ball,
// one of 20 px (a larger ball keeps its colour) is not (and is too small to be a floor).
TEST(PhotoBalls, AWashedOutOrangeSeedsOnlyAFarBall) {
  cv::Mat image = court({400, 200});
  const cv::Scalar washed_out(105, 126, 210);  // hue 12 deg, saturation 0.5
  const DrawnBall far{Vec2(40.3, 50.2), 3.0};
  cv::circle(image, {161, 50}, 20, washed_out, -1, cv::LINE_AA);
  cv::circle(image, {645, 803}, 48, washed_out, -1, cv::LINE_AA, 4);
  PhotoBallDetector detector;
  const std::vector<PhotoBall> found = detector.detect(image);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(nearest(found, far), nullptr);
}

// What a small ball must stand apart from is its own hue family: a few red-orange specks of a
// seed colour around a yellow ball (on the simulator's red court under warm lamps, the line edges
// that the floor's colours do not take out) are no field of yellow leaves; the same specks in
// the ball's yellow are.
TEST(PhotoBalls, ASmallBallStandsApartFromSpecksOfAnotherHue) {
  const DrawnBall ball{Vec2(75.3, 74.6), 2.5};
  const auto detect_with_specks = [&](const cv::Vec3b& speck) {
    cv::Mat image = court({150, 150});
    std::mt19937 random(3);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), reach(6.0, 13.0);
    for (int i = 0; i < 24; ++i) {
      const double a = angle(random), d = reach(random);
      image.at<cv::Vec3b>(static_cast<int>(std::lround(ball.center.y() + d * std::sin(a))),
                          static_cast<int>(std::lround(ball.center.x() + d * std::cos(a)))) = speck;
    }
    draw_ball(image, ball);
    PhotoBallDetector detector;
    return detector.detect(image);
  };
  expect_found(detect_with_specks({40, 75, 230}), {ball});  // hue 11 deg
  EXPECT_TRUE(detect_with_specks({40, 200, 175}).empty());  // the ball's own yellow
}

// A flat scrap of a ball's yellow on the court (a wrapper, seen from far: 10 px long, its top
// lit, its lower edge in its own shade), lying at any angle: its brightest part fits a small
// circle, but a tiny ball's blob is not 4 px longer than its disc. The ball of that size beside
// it is found.
TEST(PhotoBalls, IgnoresAFlatScrapOfABallsColour) {
  for (const double angle_deg : {0.0, 45.0, 100.0}) {
    SCOPED_TRACE("scrap at " + std::to_string(angle_deg) + " deg");
    cv::Mat image = court({200, 100});
    const double a = angle_deg * std::numbers::pi / 180.0;
    const auto at = [&](double along, double across) {  // around (50, 50), turned by the angle
      return cv::Point(
          static_cast<int>(std::lround(50 + along * std::cos(a) - across * std::sin(a))),
          static_cast<int>(std::lround(50 + along * std::sin(a) + across * std::cos(a))));
    };
    cv::fillConvexPoly(image, std::vector<cv::Point>{at(-5, 1.5), at(0, -2.5), at(5, 1.5)},
                       cv::Scalar(40, 200, 175), cv::LINE_AA);
    cv::fillConvexPoly(image, std::vector<cv::Point>{at(-3, 1), at(0, -2), at(3, 1)},
                       cv::Scalar(45, 245, 220), cv::LINE_AA);
    const DrawnBall ball{Vec2(150.3, 50.4), 2.5};
    draw_ball(image, ball);
    PhotoBallDetector detector;
    expect_found(detector.detect(image), {ball});
  }
}

TEST(PhotoBalls, GivesTheWholeCircleOfABallCutByTheBorder) {
  expect_found_when_drawn({300, 200}, {{Vec2(20, 150), 45}});  // a third outside the image
}

TEST(PhotoBalls, IgnoresALineAndFoliageOfABallsColour) {
  cv::Mat image = court({400, 300});
  cv::line(image, {20, 50}, {380, 60}, cv::Scalar(40, 230, 200), 3);  // a painted line
  std::mt19937 random(3);
  std::uniform_int_distribution<int> x(40, 360), y(150, 280);
  cv::rectangle(image, {30, 140}, {370, 290}, cv::Scalar(40, 90, 50), -1);  // dark foliage
  for (int i = 0; i < 300; ++i)                                             // sunlit leaves
    cv::circle(image, {x(random), y(random)}, 2, cv::Scalar(40, 200, 170), -1);
  PhotoBallDetector detector;
  EXPECT_TRUE(detector.detect(image).empty());
}

// A round patch of weeds of a ball's colour, standing alone on the court, passes every test of
// shape and colour; its sunlit leaves and the dark gaps between them make it far rougher than a
// ball's felt, which stays smooth under strong sensor noise.
TEST(PhotoBalls, WeedsAreTooRoughForABallAndANoisyBallIsNot) {
  cv::Mat image = court({300, 150});
  // Sunlit leaves, shaded leaves and the gaps between them, pixel by pixel.
  const cv::Scalar leaves[] = {{40, 235, 205}, {25, 140, 115}, {15, 50, 40}};
  std::mt19937 random(7);
  std::discrete_distribution<int> leaf({0.45, 0.35, 0.2});
  for (int y = 63; y <= 87; ++y)
    for (int x = 63; x <= 87; ++x)
      if ((Vec2(x, y) - Vec2(75, 75)).norm() <= 12.0)
        cv::rectangle(image, {x, y}, {x, y}, leaves[leaf(random)]);
  const DrawnBall ball{Vec2(225, 75), 12};
  cv::Mat ball_layer = court({300, 150});
  draw_ball(ball_layer, ball);
  cv::Mat noise(image.size(), CV_16SC3);
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(10));
  cv::Mat noisy;
  cv::add(ball_layer, noise, noisy, cv::noArray(), CV_8UC3);
  noisy(cv::Rect(150, 0, 150, 150)).copyTo(image(cv::Rect(150, 0, 150, 150)));
  PhotoBallDetector detector;
  expect_found(detector.detect(image), {ball});
}

// In a hard shadow the court and the balls get only the sky's light: a quarter of their sunlit
// brightness, and the camera's noise stays. The default colour model finds the balls there (their
// hue and saturation hold), and their felt is still smooth enough.
TEST(PhotoBalls, FindsBallsInAHardShadow) {
  cv::Mat image = court({200, 200});
  const std::vector<DrawnBall> balls{{Vec2(60, 100), 4}, {Vec2(140, 100), 15}};
  for (const DrawnBall& b : balls) draw_ball(image, b);
  image *= 0.25;
  cv::Mat noise(image.size(), CV_16SC3);
  cv::theRNG().state = 11;
  cv::randn(noise, cv::Scalar::all(0), cv::Scalar::all(4));
  cv::add(image, noise, image, cv::noArray(), CV_8UC3);
  PhotoBallDetector detector;
  expect_found(detector.detect(image), balls);
}

// Far balls in a JPEG: at 2-3 px radius the 4:2:0 chroma subsampling averages an orange ball's
// colour with the court's over 2 x 2 pixels, so its core keeps its hue at about half its
// saturation and its sunlit top turns pale (on the real photos, docs/RESULTS.md: 0.4-0.7 and
// 0.15-0.3). The "stage orange, far" colour finds such balls: over 32 positions each, these two
// were found 32 times with it and 2 and 1 times without it. A yellow ball as small is found too.
TEST(PhotoBalls, FindsFarOrangeBallsInAJpeg) {
  cv::Mat image = court({160, 100});
  const std::vector<std::pair<DrawnBall, cv::Scalar>> orange{
      {{Vec2(40.0, 50.0), 2.5}, cv::Scalar(60, 100, 210)},
      {{Vec2(80.5, 51.4), 3.0}, cv::Scalar(70, 110, 200)}};
  for (const auto& [b, bgr] : orange) {
    const cv::Point c(static_cast<int>(std::lround(b.center.x() * 16)),
                      static_cast<int>(std::lround(b.center.y() * 16)));
    const int r = static_cast<int>(std::lround(b.radius * 16));
    cv::circle(image, c, r, bgr, -1, cv::LINE_AA, 4);
    cv::circle(image, {c.x, c.y - r / 3}, r / 2, cv::Scalar(150, 175, 235), -1, cv::LINE_AA, 4);
  }
  const DrawnBall yellow{Vec2(120.4, 50.3), 2.5};
  draw_ball(image, yellow);
  std::vector<uchar> jpeg;  // OpenCV 4.6 writes libjpeg's default, 4:2:0
  ASSERT_TRUE(cv::imencode(".jpg", image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 90}));
  PhotoBallDetector detector;
  const std::vector<PhotoBall> found = detector.detect(cv::imdecode(jpeg, cv::IMREAD_COLOR));
  EXPECT_EQ(found.size(), 3u);
  for (const DrawnBall& b : {orange[0].first, orange[1].first, yellow})
    EXPECT_NE(nearest(found, b), nullptr) << "ball at (" << b.center.transpose() << ")";
}

// A concrete court under a hall's warm lamps (blue x 0.8, red x 1.12): the grey floor and its
// white lines turn to a tennis ball's growth colours; the floor's colours are taken out as floor,
// but a thin line's (a few pixels of each colour) are not, and it counts as rough specks around
// the small balls lying near it. The cast is read off the brightest near-neutral pixels (the
// lines and the floor's brightest noise) and corrected.
TEST(PhotoBalls, FindsBallsUnderAWarmLamp) {
  cv::Mat image = court({640, 480}, 1, cv::Scalar::all(125));
  cv::line(image, {0, 100}, {639, 130}, cv::Scalar::all(215), 1, cv::LINE_AA);
  cv::line(image, {0, 300}, {639, 290}, cv::Scalar::all(215), 1, cv::LINE_AA);
  const std::vector<DrawnBall> balls{{Vec2(60.3, 109.2), 2.5},
                                     {Vec2(400.2, 110.7), 3.0},
                                     {Vec2(250.5, 302.5), 3.5},
                                     {Vec2(530.5, 285.5), 6.0}};
  for (const DrawnBall& b : balls) draw_ball(image, b);
  cv::multiply(image, cv::Scalar(0.8, 1.0, 1.12), image);
  PhotoBallDetector detector;
  expect_found(detector.detect(image), balls);
}

// The image is searched in horizontal bands in parallel; a blob belongs to the band of its first
// seed pixel. Balls across the band borders (for 2, 3 and 7 bands), one whose pale top (growth
// colour only) reaches into the band above its first seed, touching balls, leaves, and two
// clumps of small balls close together, each the first clump of its band with 7 bands (their
// clumps are told apart; each has the other in its wide ring): every band count gives the same
// balls in the same order as one band.
void expect_same_balls(const std::vector<PhotoBall>& found, const std::vector<PhotoBall>& expected,
                       const std::string& what) {
  ASSERT_EQ(found.size(), expected.size()) << what;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(found[i].center_px, expected[i].center_px) << what << ", ball " << i;
    EXPECT_EQ(found[i].radius_px, expected[i].radius_px) << what << ", ball " << i;
    EXPECT_EQ(found[i].score, expected[i].score) << what << ", ball " << i;
  }
}

// On the blue court, and on a wooden floor (searched a second time without the floor's colours).
TEST(PhotoBalls, TheBandsDoNotChangeTheBalls) {
  for (const cv::Scalar& floor : {cv::Scalar(150, 120, 95), cv::Scalar(100, 150, 195)}) {
    cv::Mat image = court({420, 300}, 1, floor);
    const std::vector<DrawnBall> balls{{Vec2(60, 150), 25},  {Vec2(110, 150), 25},
                                       {Vec2(200, 100), 12}, {Vec2(300, 200), 40},
                                       {Vec2(380, 43), 6},   {Vec2(30, 257), 4}};
    for (const DrawnBall& b : balls) draw_ball(image, b);
    const DrawnBall pale_topped{Vec2(200, 160), 20};
    draw_ball(image, pale_topped);
    cv::ellipse(image, {200, 160}, {22, 22}, 0, 180, 360, cv::Scalar(140, 200, 190), -1);
    for (const double row : {37.0, 49.0})  // in bands 0 and 1 of 7
      for (const double column : {250.0, 257.4}) draw_ball(image, {Vec2(column, row), 3.5});
    std::mt19937 random(5);
    std::uniform_int_distribution<int> x(0, 419), y(0, 299);
    for (int i = 0; i < 60; ++i) {  // leaves; one beside the pale top would be a seed above it
      const cv::Point leaf(x(random), y(random));
      if ((Vec2(leaf.x, leaf.y) - pale_topped.center).norm() > 30.0)
        cv::circle(image, leaf, 1, {40, 200, 170}, -1);
    }
    PhotoBallOptions options;
    options.bands = 1;
    const std::vector<PhotoBall> one = PhotoBallDetector(options).detect(image);
    ASSERT_GE(one.size(), balls.size() + 1);
    ASSERT_NE(nearest(one, pale_topped), nullptr);
    for (const int bands : {2, 3, 7}) {
      options.bands = bands;
      expect_same_balls(PhotoBallDetector(options).detect(image), one,
                        std::to_string(bands) + " bands on floor " + std::to_string(floor[2]));
    }
  }
}

// A detector that took a photo's floor colours out forgets them for the next photo: there, an
// orange ball whose shaded half is of the wood's colour is found whole.
TEST(PhotoBalls, TheFloorOfOnePhotoIsNotTheNext) {
  const cv::Scalar wood_bgr(100, 150, 195);
  cv::Mat wood = court({320, 240}, 1, wood_bgr);
  draw_ball(wood, {Vec2(160, 120), 12});
  cv::Mat blue = court({320, 240});
  cv::circle(blue, {100, 120}, 14, wood_bgr, -1, cv::LINE_AA);
  cv::circle(blue, {100, 116}, 10, cv::Scalar(60, 140, 235), -1, cv::LINE_AA);
  PhotoBallDetector fresh, used;
  ASSERT_EQ(used.detect(wood).size(), 1u);
  const std::vector<PhotoBall> expected = fresh.detect(blue);
  ASSERT_EQ(expected.size(), 1u);
  EXPECT_NEAR(expected[0].radius_px, 14.0, 1.5);
  expect_same_balls(used.detect(blue), expected, "after the wooden floor");
}

TEST(PhotoBalls, RefusesAnImageThatIsNotColour) {
  PhotoBallDetector detector;
  EXPECT_THROW(detector.detect(cv::Mat1b(10, 10)), InputError);
  EXPECT_THROW(detector.detect(cv::Mat()), InputError);
}

TEST(PhotoBalls, ValidatesItsOptions) {
  PhotoBallOptions options;
  options.circles.max_radius_px = 1.0;
  EXPECT_THROW(PhotoBallDetector{options}, InputError);
  options = {};
  options.colours.colours.clear();
  EXPECT_THROW(PhotoBallDetector{options}, InputError);
  options = {};
  options.bands = -1;
  EXPECT_THROW(PhotoBallDetector{options}, InputError);
}

}  // namespace
}  // namespace ballsight
