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
  // A token under 16 characters, and a file that cannot be created: errors naming the file.
  write_file_atomic(file, "short\n");
  const auto names = [](const std::filesystem::path& bad) {
    try {
      read_or_create_token(bad);
    } catch (const InputError& e) {
      return std::string(e.what()).find(bad.string()) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(names(file));
  EXPECT_TRUE(names(dir.path() / "no-such-folder" / "token"));
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
