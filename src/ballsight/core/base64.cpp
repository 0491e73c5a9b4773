#include "ballsight/core/base64.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

}  // namespace

std::string base64(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      group <<= 8;
      if (k < n) group |= static_cast<std::uint8_t>(bytes[i + k]);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kDigits[(group >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

std::string base64_decode(std::string_view text, const std::string& where) {
  require(
      text.size() % 4 == 0, where,
      "base64 text of " + std::to_string(text.size()) + " characters (a multiple of 4 expected)");
  std::string out;
  out.reserve(text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    std::uint32_t group = 0;
    int padding = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const char c = text[i + k];
      const char* digit = c == '\0' ? nullptr : std::strchr(kDigits, c);
      const bool pad = c == '=' && i + 4 == text.size() && k >= 2 && (k == 3 || text[i + 3] == '=');
      require(digit != nullptr || pad, where,
              "not base64 at character " + std::to_string(i + k + 1));
      require(padding == 0 || pad, where, "base64 data after '=' padding");
      padding += pad ? 1 : 0;
      group = (group << 6) | static_cast<std::uint32_t>(pad ? 0 : digit - kDigits);
    }
    for (int k = 0; k < 3 - padding; ++k) out += static_cast<char>((group >> (16 - 8 * k)) & 0xFF);
  }
  return out;
}

}  // namespace ballsight
