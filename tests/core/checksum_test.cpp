#include "ballsight/core/checksum.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace ballsight {
namespace {

TEST(Crc32, MatchesTheStandardCheckValues) {
  EXPECT_EQ(crc32(0, ""), 0x00000000u);
  EXPECT_EQ(crc32(0, "123456789"), 0xCBF43926u);  // the CRC-32/ISO-HDLC check value
  EXPECT_EQ(crc32(0, "The quick brown fox jumps over the lazy dog"), 0x414FA339u);
}

TEST(Crc32, ContinuesAcrossSplitsAndSeesEveryFlippedBit) {
  const unsigned seed = 20240611;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::string bytes(997, '\0');
  for (char& b : bytes) b = static_cast<char>(rng() & 0xFFu);
  const std::uint32_t whole = crc32(0, bytes);
  for (std::size_t split : {std::size_t{0}, std::size_t{1}, std::size_t{500}, bytes.size()}) {
    const std::string_view view(bytes);
    EXPECT_EQ(crc32(crc32(0, view.substr(0, split)), view.substr(split)), whole) << split;
  }
  for (int trial = 0; trial < 200; ++trial) {
    std::string flipped = bytes;
    flipped[rng() % flipped.size()] ^= static_cast<char>(1u << (rng() % 8));
    EXPECT_NE(crc32(0, flipped), whole);
  }
}

}  // namespace
}  // namespace ballsight
