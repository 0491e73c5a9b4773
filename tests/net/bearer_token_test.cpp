#include "ballsight/net/bearer_token.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

TEST(BearerToken, TheFileIsCreatedPrivateAndReadBack) {
  const test::TempDir dir;
  const auto file = dir.path() / "token";
  const std::string token = read_or_create_token(file);
  EXPECT_EQ(token.size(), 32u);
  struct stat st {};
  ASSERT_EQ(::stat(file.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(read_or_create_token(file), token);
  write_file_atomic(file, "short\n");
  EXPECT_THROW(read_or_create_token(file), InputError);  // under 16 characters
  EXPECT_THROW(read_or_create_token(dir.path() / "no-such-dir" / "token"), InputError);
}

TEST(BearerToken, OnlyTheExactHeaderShowsIt) {
  const std::string token = "0123456789abcdef0123";
  EXPECT_TRUE(shows_token("Bearer 0123456789abcdef0123", token));
  EXPECT_FALSE(shows_token("Bearer 0123456789abcdef012", token));
  EXPECT_FALSE(shows_token("Bearer 0123456789abcdef0124", token));
  EXPECT_FALSE(shows_token("bearer 0123456789abcdef0123", token));
  EXPECT_FALSE(shows_token("0123456789abcdef0123", token));
  EXPECT_FALSE(shows_token("", token));
}

}  // namespace
}  // namespace ballsight
