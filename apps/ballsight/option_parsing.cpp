#include "option_parsing.hpp"

#include <cmath>
#include <sstream>

#include "ballsight/core/error.hpp"

namespace ballsight::app {

Vec2 parse_pixel_pair(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  double x = 0.0, y = 0.0;
  char comma = 0;
  in >> x >> comma >> y;
  require(in && comma == ',' && (in >> std::ws).eof() && std::isfinite(x) && std::isfinite(y),
          option, "expected two numbers X,Y in pixels, got '" + text + "'");
  return {x, y};
}

Eigen::Vector2i parse_image_size(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  int width = 0, height = 0;
  char times = 0;
  in >> width >> times >> height;
  require(in && times == 'x' && (in >> std::ws).eof() && width > 0 && height > 0, option,
          "expected a size WxH in pixels such as 640x480, got '" + text + "'");
  return {width, height};
}

}  // namespace ballsight::app
