#include "ballsight/sim/image_effects.hpp"

#include <array>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

constexpr int kQuantileBits = 16;
constexpr std::size_t kQuantiles = std::size_t{1} << kQuantileBits;

/// Standard normal quantiles at the midpoints of kQuantiles equal-probability bins (bisection on
/// the CDF, once).
const std::array<float, kQuantiles>& normal_quantiles() {
  static const auto table = [] {
    std::array<float, kQuantiles> q{};
    for (std::size_t i = 0; i < kQuantiles; ++i) {
      const double p = (static_cast<double>(i) + 0.5) / static_cast<double>(kQuantiles);
      double lo = -8.0, hi = 8.0;
      for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
      }
      q[i] = static_cast<float>(0.5 * (lo + hi));
    }
    return q;
  }();
  return table;
}

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

void add_quantile_noise(cv::Mat& bgr, double sigma, std::uint64_t seed) {
  require(bgr.depth() == CV_8U, "image effects", "quantile noise needs an 8-bit image");
  const std::array<float, kQuantiles>& z = normal_quantiles();
  const auto s = static_cast<float>(sigma);
  std::uint64_t state = seed;
  for (int y = 0; y < bgr.rows; ++y) {
    uchar* p = bgr.ptr<uchar>(y);
    const int n = bgr.cols * bgr.channels();
    std::uint64_t bits = 0;
    for (int i = 0; i < n; ++i) {
      if (i % 4 == 0) bits = splitmix64(state);
      const float v = static_cast<float>(p[i]) + s * z[bits & (kQuantiles - 1)];
      bits >>= kQuantileBits;
      p[i] = cv::saturate_cast<uchar>(v);
    }
  }
}

// A box smear of `length` px along `deg` (the kernel a line of that length, drawn
// anti-aliased), the image's edges repeated.
void smear(cv::Mat& bgr, double length, double deg) {
  const int half = static_cast<int>(std::ceil(length / 2.0));
  const int size = 2 * half + 1;
  cv::Mat1f kernel(size, size, 0.0f);
  const double a = rad_from_deg(deg);
  // Samples along the line, a tenth of a pixel apart, each spread bilinearly.
  const int samples = std::max(2, static_cast<int>(std::ceil(length * 10.0)));
  for (int i = 0; i < samples; ++i) {
    const double t = length * ((i + 0.5) / samples - 0.5);
    const double x = half + t * std::cos(a), y = half + t * std::sin(a);
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx)
        if (x0 + dx < size && y0 + dy < size)
          kernel(y0 + dy, x0 + dx) +=
              static_cast<float>((dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy));
  }
  kernel /= cv::sum(kernel)[0];
  cv::filter2D(bgr, bgr, -1, kernel, cv::Point(-1, -1), 0.0, cv::BORDER_REPLICATE);
}

}  // namespace

void ImageEffects::validate() const {
  require(std::isfinite(brightness_gain) && brightness_gain > 0.0 && brightness_gain <= 4.0,
          "brightness", "gain must be in (0, 4]");
  require(std::isfinite(blur_sigma_px) && blur_sigma_px >= 0.0 && blur_sigma_px <= 10.0, "blur",
          "sigma must be in [0, 10] px");
  require(std::isfinite(noise_sigma) && noise_sigma >= 0.0 && noise_sigma <= 64.0, "noise",
          "sigma must be in [0, 64] grey levels");
  require(std::isfinite(motion_blur_px) && motion_blur_px >= 0.0 && motion_blur_px <= 64.0,
          "motion_blur", "length must be in [0, 64] px");
  require(std::isfinite(motion_blur_deg), "motion_blur", "direction must be finite");
  require(jpeg_quality >= 0 && jpeg_quality <= 100, "jpeg_quality",
          "must be in [1, 100], or 0 for none");
  for (int c = 0; c < 3; ++c)
    require(std::isfinite(channel_gain[c]) && channel_gain[c] > 0.0 && channel_gain[c] <= 2.0,
            "channel_gain", "each channel's gain must be in (0, 2]");
}

void apply_image_effects(cv::Mat& bgr, const ImageEffects& effects, std::uint64_t seed) {
  effects.validate();
  if (effects.channel_gain != cv::Vec3d(1.0, 1.0, 1.0)) {
    const cv::Vec3d gain = effects.brightness_gain * effects.channel_gain;
    cv::multiply(bgr, cv::Scalar(gain[0], gain[1], gain[2]), bgr);
  } else if (effects.brightness_gain != 1.0) {
    bgr.convertTo(bgr, -1, effects.brightness_gain);
  }
  if (effects.blur_sigma_px > 0.0) {
    cv::GaussianBlur(bgr, bgr, cv::Size(), effects.blur_sigma_px);
  }
  if (effects.motion_blur_px > 0.0) smear(bgr, effects.motion_blur_px, effects.motion_blur_deg);
  if (effects.noise_sigma > 0.0 && effects.quantile_noise) {
    add_quantile_noise(bgr, effects.noise_sigma, seed);
  } else if (effects.noise_sigma > 0.0) {
    cv::Mat noise(bgr.size(), CV_16SC3);
    cv::RNG rng(seed);
    rng.fill(noise, cv::RNG::NORMAL, 0.0, effects.noise_sigma);
    cv::Mat sum;
    bgr.convertTo(sum, CV_16SC3);
    sum += noise;
    sum.convertTo(bgr, CV_8UC3);
  }
  if (effects.jpeg_quality > 0) {
    std::vector<uchar> bytes;
    cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, effects.jpeg_quality});
    bgr = cv::imdecode(bytes, cv::IMREAD_COLOR);
  }
}

}  // namespace ballsight::sim
