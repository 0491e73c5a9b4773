#include "ballsight/core/glob.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "ballsight/core/error.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

TEST(Glob, WildcardsMatchLikeAShell) {
  EXPECT_TRUE(wildcard_match("left*.jpg", "left01.jpg"));
  EXPECT_TRUE(wildcard_match("left*.jpg", "left.jpg"));
  EXPECT_FALSE(wildcard_match("left*.jpg", "left01.png"));
  EXPECT_TRUE(wildcard_match("left?1.jpg", "left01.jpg"));
  EXPECT_FALSE(wildcard_match("left?.jpg", "left01.jpg"));
  EXPECT_TRUE(wildcard_match("*", ""));
  EXPECT_TRUE(wildcard_match("*a*b*", "xxaYYbZ"));
  EXPECT_FALSE(wildcard_match("*a*b", "xxaYYbZ"));
  EXPECT_TRUE(wildcard_match("a**b", "ab"));
  EXPECT_TRUE(wildcard_match("cam0_board_??.png", "cam0_board_07.png"));
  EXPECT_FALSE(wildcard_match("cam0_board_??.png", "cam1_board_07.png"));
  EXPECT_FALSE(wildcard_match("", "a"));
}

TEST(Glob, ListsMatchingFilesSorted) {
  test::TempDir dir;
  for (const char* name : {"b2.png", "b10.png", "a1.png", "a1.txt"}) std::ofstream(dir / name);
  std::filesystem::create_directory(dir / "c.png");  // a folder never matches
  const auto files = glob_files((dir / "*.png").string());
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0], dir / "a1.png");
  EXPECT_EQ(files[1], dir / "b10.png");
  EXPECT_EQ(files[2], dir / "b2.png");
  EXPECT_EQ(glob_files((dir / "a1.txt").string()).size(), 1u);
}

TEST(Glob, NothingMatchingIsAnInputError) {
  test::TempDir dir;
  EXPECT_THROW(glob_files((dir / "*.jpg").string()), InputError);
  EXPECT_THROW(glob_files((dir / "missing" / "*.jpg").string()), InputError);
  EXPECT_THROW(glob_files((dir / "*" / "a.jpg").string()), InputError);
}

}  // namespace
}  // namespace ballsight
