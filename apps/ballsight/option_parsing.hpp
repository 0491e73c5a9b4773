#pragma once
// Parsing of option values the library has no type for; errors name the option.

#include <Eigen/Core>
#include <string>

#include "ballsight/core/geometry.hpp"

namespace ballsight::app {

/// "X,Y" -> two finite numbers; throws InputError naming `option`.
Vec2 parse_pixel_pair(const std::string& text, const std::string& option);

/// "WxH" -> two positive integers; throws InputError naming `option`.
Eigen::Vector2i parse_image_size(const std::string& text, const std::string& option);

}  // namespace ballsight::app
