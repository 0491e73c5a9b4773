#include "ballsight/core/file_io.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "ballsight/core/error.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

std::string error_of(const fs::path& path, std::uintmax_t max_bytes) {
  try {
    read_file(path, max_bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FileIo, ReadsBackWhatWasWrittenByteForByte) {
  const test::TempDir dir;
  std::string bytes(200'000, '\0');
  for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<char>(k * 31 % 256);
  write_file_atomic(dir / "data.bin", bytes);
  EXPECT_EQ(read_file(dir / "data.bin"), bytes);
  EXPECT_FALSE(fs::exists(dir / "data.bin.tmp"));
}

// A file above the limit is refused from its size, before anything is read: a sparse file of
// 1 GiB and a byte takes no disk and no time.
TEST(FileIo, RefusesAFileAboveTheLimitBeforeReadingIt) {
  const test::TempDir dir;
  const fs::path huge = dir / "huge.csv";
  write_file_atomic(huge, "theta_deg,radius_px,distance_cm\n");
  fs::resize_file(huge, kMaxFileBytes + 1);
  const auto started = std::chrono::steady_clock::now();
  const std::string error = error_of(huge, kMaxFileBytes);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(1));
  EXPECT_NE(error.find(huge.string()), std::string::npos) << error;
  EXPECT_NE(error.find("limit of 1073741824 bytes"), std::string::npos) << error;

  write_file_atomic(dir / "eleven.txt", "eleven byte");
  EXPECT_EQ(read_file(dir / "eleven.txt", 11), "eleven byte");
  EXPECT_NE(error_of(dir / "eleven.txt", 10).find("limit of 10 bytes"), std::string::npos);
}

// A file whose size is not known in advance (/proc reports 0) is counted as it is read.
TEST(FileIo, CountsAFileOfUnknownSizeAsItIsRead) {
  EXPECT_FALSE(read_file("/proc/self/status").empty());
  EXPECT_NE(error_of("/proc/self/status", 10).find("limit of 10 bytes"), std::string::npos);
}

TEST(FileIo, NamesAFileItCannotOpen) {
  const test::TempDir dir;
  EXPECT_NE(error_of(dir / "missing.yml", kMaxFileBytes).find("missing.yml: cannot open"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
