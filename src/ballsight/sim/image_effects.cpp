#include "ballsight/sim/image_effects.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight::sim {

void ImageEffects::validate() const {
  require(std::isfinite(brightness_gain) && brightness_gain > 0.0 && brightness_gain <= 4.0,
          "brightness", "gain must be in (0, 4]");
  require(std::isfinite(blur_sigma_px) && blur_sigma_px >= 0.0 && blur_sigma_px <= 10.0, "blur",
          "sigma must be in [0, 10] px");
  require(std::isfinite(noise_sigma) && noise_sigma >= 0.0 && noise_sigma <= 64.0, "noise",
          "sigma must be in [0, 64] grey levels");
}

void apply_image_effects(cv::Mat& bgr, const ImageEffects& effects, std::uint64_t seed) {
  effects.validate();
  if (effects.brightness_gain != 1.0) bgr.convertTo(bgr, -1, effects.brightness_gain);
  if (effects.blur_sigma_px > 0.0) {
    cv::GaussianBlur(bgr, bgr, cv::Size(), effects.blur_sigma_px);
  }
  if (effects.noise_sigma > 0.0) {
    cv::Mat noise(bgr.size(), CV_16SC3);
    cv::RNG rng(seed);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, effects.noise_sigma);
    cv::Mat sum;
    bgr.convertTo(sum, CV_16SC3);
    sum += noise;
    sum.convertTo(bgr, CV_8UC3);
  }
}

}  // namespace ballsight::sim
