#include "ballsight/core/checksum.hpp"

#include <array>

namespace ballsight {

namespace {

constexpr std::array<std::uint32_t, 256> make_crc_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}

constexpr std::array<std::uint32_t, 256> kCrcTable = make_crc_table();

}  // namespace

std::uint32_t crc32(std::uint32_t crc, std::string_view bytes) {
  crc = ~crc;
  for (const char b : bytes) {
    crc = kCrcTable[(crc ^ static_cast<unsigned char>(b)) & 0xFFu] ^ (crc >> 8);
  }
  return ~crc;
}

}  // namespace ballsight
