#include "ballsight/sim/image_effects.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

cv::Mat noisy(bool quantile, std::uint64_t seed) {
  cv::Mat bgr(240, 320, CV_8UC3, cv::Scalar(100, 120, 140));
  ImageEffects effects;
  effects.noise_sigma = 3.0;
  effects.quantile_noise = quantile;
  apply_image_effects(bgr, effects, seed);
  return bgr;
}

TEST(ImageEffects, QuantileNoiseIsTheSameGaussianAsOpenCvs) {
  for (const bool quantile : {false, true}) {
    SCOPED_TRACE(quantile ? "quantile" : "opencv");
    cv::Mat diff;
    noisy(quantile, 5).convertTo(diff, CV_32FC3);
    diff -= cv::Scalar(100, 120, 140);
    cv::Scalar mean, stddev;
    cv::meanStdDev(diff.reshape(1), mean, stddev);
    EXPECT_NEAR(mean[0], 0.0, 0.02);
    // Rounded to grey levels: variance sigma^2 + 1/12.
    EXPECT_NEAR(stddev[0], std::sqrt(9.0 + 1.0 / 12.0), 0.02);
    // Tails as a normal's: 4.55 % beyond two sigma (before rounding; |d| > 6 after it).
    const double beyond = static_cast<double>(cv::countNonZero(cv::abs(diff.reshape(1)) > 6.5)) /
                          static_cast<double>(diff.total() * 3);
    EXPECT_NEAR(beyond, 0.0301, 0.002);  // P(|N(0, 3)| > 6.5)
  }
}

TEST(ImageEffects, QuantileNoiseFollowsItsSeed) {
  EXPECT_EQ(cv::norm(noisy(true, 7), noisy(true, 7), cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(noisy(true, 7), noisy(true, 8), cv::NORM_L1), 0.0);
}

TEST(ImageEffects, AColourCastScalesEachChannelOnTopOfTheBrightness) {
  cv::Mat image(4, 4, CV_8UC3, cv::Scalar(100, 100, 100));
  ImageEffects effects;
  effects.brightness_gain = 0.8;
  effects.channel_gain = {0.5, 1.0, 1.5};
  apply_image_effects(image, effects, 1);
  EXPECT_EQ(image.at<cv::Vec3b>(2, 1), cv::Vec3b(40, 80, 120));
  effects.channel_gain = {1.0, 0.0, 1.0};
  EXPECT_THROW(apply_image_effects(image, effects, 1), InputError);
}

// A white dot smeared along a direction spreads over the smear's length along it and stays one
// pixel wide across it; the light it spreads is kept.
TEST(ImageEffects, AMotionBlurSmearsAlongItsDirection) {
  for (const double deg : {0.0, 90.0, 30.0}) {
    SCOPED_TRACE(deg);
    cv::Mat image(41, 41, CV_8UC3, cv::Scalar::all(0));
    image.at<cv::Vec3b>(20, 20) = cv::Vec3b(250, 250, 250);
    ImageEffects effects;
    effects.motion_blur_px = 10.0;
    effects.motion_blur_deg = deg;
    apply_image_effects(image, effects, 1);
    cv::Mat grey;
    cv::extractChannel(image, grey, 0);
    EXPECT_NEAR(cv::sum(grey)[0], 250.0, 12.0);  // rounding per pixel
    double spread_along = 0.0, spread_across = 0.0, total = 0.0;
    const double a = deg * std::numbers::pi / 180.0;
    for (int y = 0; y < grey.rows; ++y)
      for (int x = 0; x < grey.cols; ++x) {
        const double w = grey.at<uchar>(y, x);
        const double u = (x - 20) * std::cos(a) + (y - 20) * std::sin(a);
        const double v = -(x - 20) * std::sin(a) + (y - 20) * std::cos(a);
        spread_along += w * u * u;
        spread_across += w * v * v;
        total += w;
      }
    // A box of length L has a variance of L^2 / 12; across it, the spread of the bilinear taps.
    EXPECT_NEAR(std::sqrt(spread_along / total), 10.0 / std::sqrt(12.0), 0.4);
    EXPECT_LT(std::sqrt(spread_across / total), 0.5);
  }
  ImageEffects bad;
  bad.motion_blur_px = -1.0;
  EXPECT_THROW(bad.validate(), InputError);
}

// Saved as a JPEG and decoded: the blocks and the halved chroma of a phone's or an IP camera's
// frame, the same bytes for the same quality, and a smaller change at a higher quality.
TEST(ImageEffects, AJpegRoundTripLosesDetailByItsQuality) {
  cv::Mat image(64, 64, CV_8UC3, cv::Scalar(90, 140, 60));
  cv::circle(image, {30, 30}, 6, cv::Scalar(45, 235, 215), -1, cv::LINE_AA);
  const auto saved = [&](int quality) {
    cv::Mat out = image.clone();
    ImageEffects effects;
    effects.jpeg_quality = quality;
    apply_image_effects(out, effects, 1);
    return out;
  };
  EXPECT_EQ(cv::norm(saved(40), saved(40), cv::NORM_INF), 0.0);
  const double low = cv::norm(saved(20), image, cv::NORM_L1);
  const double high = cv::norm(saved(95), image, cv::NORM_L1);
  EXPECT_GT(low, 0.0);
  EXPECT_LT(high, low);
  ImageEffects bad;
  bad.jpeg_quality = 101;
  EXPECT_THROW(bad.validate(), InputError);
}

}  // namespace
}  // namespace ballsight::sim
