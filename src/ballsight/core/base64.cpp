#include "ballsight/core/base64.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

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
  // Each character's 6-bit value, or -1 for one that is not a base64 digit.
  static const std::array<int, 256> kValues = [] {
    std::array<int, 256> values;
    values.fill(-1);
    for (int v = 0; v < 64; ++v) values[static_cast<unsigned char>(kDigits[v])] = v;
    return values;
  }();
  if (text.size() % 4 != 0) {
    throw InputError(where + ": base64 text of " + std::to_string(text.size()) +
                     " characters (a multiple of 4 expected)");
  }
  std::string out;
  out.reserve(text.size() / 4 * 3);
  for (std::size_t i = 0; i < text.size(); i += 4) {
    std::uint32_t group = 0;
    int padding = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const char c = text[i + k];
      const int value = kValues[static_cast<unsigned char>(c)];
      const bool pad = c == '=' && i + 4 == text.size() && k >= 2 && (k == 3 || text[i + 3] == '=');
      if (value < 0 && !pad) {
        throw InputError(where + ": not base64 at character " + std::to_string(i + k + 1));
      }
      if (padding > 0 && !pad) throw InputError(where + ": base64 data after '=' padding");
      padding += pad ? 1 : 0;
      group = (group << 6) | static_cast<std::uint32_t>(pad ? 0 : value);
    }
    for (int k = 0; k < 3 - padding; ++k) out += static_cast<char>((group >> (16 - 8 * k)) & 0xFF);
  }
  return out;
}

}  // namespace ballsight
