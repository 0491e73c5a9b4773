#include "ballsight/sim/image_effects.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

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

}  // namespace
}  // namespace ballsight::sim
