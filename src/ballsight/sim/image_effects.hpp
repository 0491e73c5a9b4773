#pragma once
// Camera effects applied to a rendered frame: brightness gain, colour cast, blur and sensor noise.

#include <cstdint>
#include <opencv2/core.hpp>

namespace ballsight::sim {

struct ImageEffects {
  double brightness_gain = 1.0;  // multiplies every channel
  double blur_sigma_px = 0.0;    // Gaussian blur, 0 = none
  double noise_sigma = 0.0;      // Gaussian sensor noise in grey levels, 0 = none
  /// Noise drawn as quantiles of the normal (65536 equal-probability bins, indexed by a 64-bit
  /// SplitMix stream): the same rounded Gaussian, three times as fast as OpenCV's generator that
  /// the recorded results used (false). The closed loop renders 40 views a simulated second.
  bool quantile_noise = false;
  /// A colour cast: each channel's gain (B, G, R) on top of brightness_gain, as a white balance
  /// left slightly off by a light that is not daylight leaves it.
  cv::Vec3d channel_gain{1.0, 1.0, 1.0};
  /// A camera or a robot moving during the exposure: a straight smear of this length (a box
  /// along the direction), 0 = none.
  double motion_blur_px = 0.0;
  double motion_blur_deg = 0.0;  // its direction in the image, from +x towards +y
  /// The frame saved as a JPEG of this quality (1-100, OpenCV's encoder: 4:2:0 chroma) and
  /// decoded, as a phone or an IP camera delivers it; 0 = none.
  int jpeg_quality = 0;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// Applies the effects in camera order (light -> optics -> motion -> sensor -> encoder), in
/// place. Noise is drawn
/// from `seed`, so the same seed gives the same bytes.
void apply_image_effects(cv::Mat& bgr, const ImageEffects& effects, std::uint64_t seed);

}  // namespace ballsight::sim
