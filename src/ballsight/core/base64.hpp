#pragma once
// Base64 (RFC 4648, with padding): bytes inside JSON, such as a camera frame in a data: URL.

#include <string>
#include <string_view>

namespace ballsight {

std::string base64(std::string_view bytes);

}  // namespace ballsight
