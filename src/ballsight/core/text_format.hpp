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

}  // namespace ballsight
