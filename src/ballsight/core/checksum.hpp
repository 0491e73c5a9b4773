#pragma once
// CRC-32 (IEEE 802.3 polynomial, reflected; the same value as zlib's crc32 and Python's
// zlib.crc32), for file checksums. A few lines instead of a zlib dependency.

#include <cstdint>
#include <string_view>

namespace ballsight {

/// Continues a CRC-32 over `bytes`; start with crc = 0. crc32(crc32(0, a), b) == crc32(0, a + b).
std::uint32_t crc32(std::uint32_t crc, std::string_view bytes);

}  // namespace ballsight
