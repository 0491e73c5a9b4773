#include "ballsight/core/little_endian.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace ballsight {
namespace {

TEST(LittleEndian, WritesLeastSignificantByteFirst) {
  std::string bytes;
  LittleEndianWriter out(bytes);
  out.u32(0x01020304u);
  out.i16(-2);
  out.f32(1.0f);  // 0x3F800000
  ASSERT_EQ(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 4), std::string("\x04\x03\x02\x01", 4));
  EXPECT_EQ(bytes.substr(4, 2), std::string("\xFE\xFF", 2));
  EXPECT_EQ(bytes.substr(6, 4), std::string("\x00\x00\x80\x3F", 4));
}

TEST(LittleEndian, RoundTripsEveryFieldType) {
  std::string bytes;
  LittleEndianWriter out(bytes);
  out.u16(0xBEEF);
  out.i16(std::numeric_limits<std::int16_t>::min());
  out.u32(0xDEADBEEFu);
  out.u64(0x0123456789ABCDEFull);
  out.f32(std::numeric_limits<float>::quiet_NaN());
  out.f64(-1234.5678e-9);
  out.padded("method", 10);
  LittleEndianReader in(bytes);
  EXPECT_EQ(in.u16(), 0xBEEF);
  EXPECT_EQ(in.i16(), std::numeric_limits<std::int16_t>::min());
  EXPECT_EQ(in.u32(), 0xDEADBEEFu);
  EXPECT_EQ(in.u64(), 0x0123456789ABCDEFull);
  EXPECT_TRUE(std::isnan(in.f32()));
  EXPECT_EQ(in.f64(), -1234.5678e-9);
  EXPECT_EQ(in.padded(10), "method");
  EXPECT_EQ(in.offset(), bytes.size());
}

}  // namespace
}  // namespace ballsight
