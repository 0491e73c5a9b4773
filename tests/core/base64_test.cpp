#include "ballsight/core/base64.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

// RFC 4648, section 10.
TEST(Base64, RfcTestVectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\xfe\x00", 3)), "//4A");
}

TEST(Base64, DecodesWhatItEncodesAndRefusesTheRest) {
  for (const std::string bytes : {"", "f", "fo", "foo", "foob", "fooba", "foobar"}) {
    EXPECT_EQ(base64_decode(base64(bytes), "t"), bytes);
  }
  const std::string all = [] {
    std::string b;
    for (int i = 0; i < 256; ++i) b += static_cast<char>(i);
    return b;
  }();
  EXPECT_EQ(base64_decode(base64(all), "t"), all);
  for (const char* bad : {"Zg=", "Z=g=", "Zg=x", "Zm9v!A==", "Zg==Zg==", "Zm 9"}) {
    EXPECT_THROW(base64_decode(bad, "t"), InputError) << bad;
  }
}

}  // namespace
}  // namespace ballsight
