#include "ballsight/detect/hue_classes.hpp"

#include <algorithm>
#include <string>

#include "ballsight/core/error.hpp"

namespace ballsight {

void HueBand::validate(const char* name) const {
  require(hue_min_deg >= 0.0 && hue_min_deg <= 360.0 && hue_max_deg >= 0.0 && hue_max_deg <= 360.0,
          name, "hue bounds must be within [0, 360] degrees");
  require(min_chroma >= 0.0 && min_chroma <= 255.0, name, "min_chroma must be within [0, 255]");
  require(min_saturation >= 0.0 && min_saturation <= 1.0, name,
          "min_saturation must be within [0, 1]");
  require(min_value >= 0.0 && min_value <= 255.0, name, "min_value must be within [0, 255]");
}

double hue_deg(const cv::Vec3b& bgr) {
  const double b = bgr[0], g = bgr[1], r = bgr[2];
  const double hi = std::max({b, g, r}), lo = std::min({b, g, r});
  const double chroma = hi - lo;
  if (chroma <= 0.0) return 0.0;
  double hue = 0.0;
  if (hi == r) {
    hue = 60.0 * (g - b) / chroma;
  } else if (hi == g) {
    hue = 60.0 * (b - r) / chroma + 120.0;
  } else {
    hue = 60.0 * (r - g) / chroma + 240.0;
  }
  return hue < 0.0 ? hue + 360.0 : hue;
}

double saturation(const cv::Vec3b& bgr) {
  const int hi = std::max({bgr[0], bgr[1], bgr[2]}), lo = std::min({bgr[0], bgr[1], bgr[2]});
  return hi > 0 ? static_cast<double>(hi - lo) / hi : 0.0;
}

bool HueBand::contains(const cv::Vec3b& bgr) const {
  const int hi = std::max({bgr[0], bgr[1], bgr[2]}), lo = std::min({bgr[0], bgr[1], bgr[2]});
  if (hi - lo < min_chroma || hi == lo || hi < min_value) return false;
  if (hi - lo < min_saturation * hi) return false;
  const double hue = hue_deg(bgr);
  return hue_min_deg <= hue_max_deg ? hue >= hue_min_deg && hue <= hue_max_deg
                                    : hue >= hue_min_deg || hue <= hue_max_deg;
}

ColorClassTable hue_class_table(const std::vector<HueClassRule>& rules) {
  for (const HueClassRule& rule : rules) rule.band.validate("hue class");
  return ColorClassTable::from_classifier([&rules](const cv::Vec3b& bgr) {
    ColorClassMask mask = 0;
    for (const HueClassRule& rule : rules)
      if (rule.band.contains(bgr)) mask |= rule.mask;
    return mask;
  });
}

}  // namespace ballsight
