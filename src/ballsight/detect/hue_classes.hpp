#pragma once
// Colour classes as hue bands: a saturated object keeps its hue when the light changes (sun,
// shadow, exposure), only its brightness and chroma scale, so a band of hue with a floor on chroma
// finds it in the sun and in the shade. Compiled into a ColorClassTable (one read per pixel).

#include <opencv2/core.hpp>
#include <vector>

#include "ballsight/detect/color_classes.hpp"

namespace ballsight {

/// Hue in degrees (0 red, 120 green, 240 blue; a band with min > max wraps through 0), chroma
/// (max - min of B, G, R, 0-255), saturation (chroma / max, 0-1) and value (max of B, G, R, 0-255)
/// of 8-bit BGR colours.
struct HueBand {
  double hue_min_deg = 0.0;
  double hue_max_deg = 360.0;
  double min_chroma = 0.0;
  double min_saturation = 0.0;
  double min_value = 0.0;

  /// Throws InputError naming `name` when a bound is out of range.
  void validate(const char* name) const;
  bool contains(const cv::Vec3b& bgr) const;
};

/// Hue of a colour, degrees in [0, 360) (0 for greys).
double hue_deg(const cv::Vec3b& bgr);

/// Saturation of a colour: chroma / max of B, G, R, in [0, 1] (0 for black).
double saturation(const cv::Vec3b& bgr);

struct HueClassRule {
  ColorClassMask mask = 0;
  HueBand band;
};

/// The table of a set of hue-band rules.
ColorClassTable hue_class_table(const std::vector<HueClassRule>& rules);

}  // namespace ballsight
