#pragma once
// Numbers for people: reports and command-line output.

#include <cstdio>
#include <string>

namespace ballsight {

/// `value` with exactly `decimals` digits after the point ("%.*f").
inline std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

/// "(x, y)" with `decimals` digits after the point.
inline std::string fixed_pair(double x, double y, int decimals) {
  std::string text = "(";  // appended piece by piece: GCC 12 warns wrongly on "(" + std::string
  text += fixed(x, decimals);
  text += ", ";
  text += fixed(y, decimals);
  text += ")";
  return text;
}

}  // namespace ballsight
