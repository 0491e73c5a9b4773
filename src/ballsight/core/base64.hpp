#pragma once
// Base64 (RFC 4648, with padding): bytes inside JSON, such as a camera frame in a data: URL.

#include <string>
#include <string_view>

namespace ballsight {

std::string base64(std::string_view bytes);
/// The bytes of base64 `text` (with padding); throws InputError naming `where` for anything else.
std::string base64_decode(std::string_view text, const std::string& where);

}  // namespace ballsight
