// `ballsight omni inspect` end to end: the built binary on real, hand-made and broken tables.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "apps/run_cli.hpp"
#include "ballsight/core/checksum.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/little_endian.hpp"
#include "shared_data.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

class OmniInspectCli : public ::testing::Test {
 protected:
  static test::CliResult inspect(std::vector<std::string> args) {
    args.insert(args.begin(), {"omni", "inspect"});
    return test::run_cli(args);
  }

  /// A bad input: non-zero exit and exactly one line on stderr naming the file and the problem.
  static void expect_rejected(const fs::path& file, const std::string& problem) {
    const test::CliResult r = inspect({file.string()});
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(r.stdout_text, "");
    EXPECT_EQ(test::line_count(r.stderr_text), 1) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(file.string()), std::string::npos) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(problem), std::string::npos) << r.stderr_text;
  }

  test::TempDir dir;
};

// A ballsight table written field by field from docs/lut-format.md, independently of the
// library's writer: a 64 x 48 image whose cells are 3 cm per pixel straight out from the centre.
std::string documented_ground_map(std::uint32_t version = 1) {
  const int width = 64, height = 48;
  const double cx = 31.5, cy = 23.5, min_r = 5.0, max_r = 20.0;
  std::string file;
  LittleEndianWriter out(file);
  out.padded("BSGRDMAP", 8);
  out.u32(version);
  out.u32(144);
  out.u32(width);
  out.u32(height);
  out.f64(cx);
  out.f64(cy);
  out.f64(min_r);
  out.f64(max_r);
  out.u32(1);  // cm
  out.u32(1);  // float32 pairs
  out.u64(std::uint64_t{width} * height * 8);
  out.padded("hand-written", 64);
  out.u32(0);  // reserved
  out.u32(0);  // checksum, below
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double r = std::hypot(x - cx, y - cy);
      const bool stored = r >= min_r - 1.5 && r <= max_r + 1.5;
      const float nan = std::numeric_limits<float>::quiet_NaN();
      out.f32(stored ? static_cast<float>(3.0 * (cy - y)) : nan);  // forward: image up
      out.f32(stored ? static_cast<float>(3.0 * (cx - x)) : nan);  // left: image left
    }
  }
  const std::uint32_t crc =
      crc32(crc32(0, std::string_view(file).substr(0, 140)), std::string_view(file).substr(144));
  std::string crc_bytes;
  LittleEndianWriter(crc_bytes).u32(crc);
  file.replace(140, 4, crc_bytes);
  return file;
}

TEST_F(OmniInspectCli, ReportsAHandWrittenBallsightTable) {
  const fs::path table = dir / "hand.bsgm";
  write_file_atomic(table, documented_ground_map());
  const test::CliResult r = inspect({table.string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const std::string& out = r.stdout_text;
  EXPECT_NE(out.find("format                     ballsight\n"), std::string::npos) << out;
  EXPECT_NE(out.find("first_written_px           min 5.0"), std::string::npos) << out;
  EXPECT_NE(out.find("non_monotonic_directions   0\n"), std::string::npos) << out;
  EXPECT_NE(out.find("holes                      count 0 "), std::string::npos) << out;
}

TEST_F(OmniInspectCli, FindsTheRealIrisTablesNonMonotonicRegionAndPlotsIt) {
  const auto tables = test::iris_px2cm_tables();
  if (tables.empty()) BALLSIGHT_SKIP() << "no iris px2cm tables in " << test::shared_data_dir();
  const fs::path png = dir / "inspect.png";
  const test::CliResult r = inspect(
      {tables.front().string(), "--format", "iris-px2cm", "--json", "--plot", png.string()});
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(r.stderr_text, "");
  const std::size_t key = r.stdout_text.find("\"monotonic_until_px\": ");
  ASSERT_NE(key, std::string::npos) << r.stdout_text;
  const double until_px = std::stod(r.stdout_text.substr(key + 22));
  EXPECT_GE(until_px, 175.0);
  EXPECT_LE(until_px, 210.0);
  ASSERT_TRUE(fs::exists(png));
  EXPECT_EQ(read_file(png).substr(1, 3), "PNG");
}

TEST_F(OmniInspectCli, BadFilesExitNonZeroWithOneLine) {
  const std::string good = documented_ground_map();
  const fs::path table = dir / "table.bsgm";
  write_file_atomic(table, good.substr(0, good.size() - 100));
  expect_rejected(table, "truncated: expected " + std::to_string(good.size()) + " bytes, got " +
                             std::to_string(good.size() - 100));
  std::string corrupt = good;
  corrupt[1000] = static_cast<char>(corrupt[1000] ^ 0x01);
  write_file_atomic(table, corrupt);
  expect_rejected(table, "checksum mismatch");
  write_file_atomic(table, documented_ground_map(7));
  expect_rejected(table, "version 7 not supported (expected 1)");
  write_file_atomic(table, "");
  expect_rejected(table, "empty file");
  write_file_atomic(table, "not a table");
  expect_rejected(table, "unknown table format");
  expect_rejected(dir / "missing.bsgm", "cannot open");
}

TEST_F(OmniInspectCli, BadOptionsExitNonZeroWithOneLine) {
  const test::CliResult r = inspect({"table.bsgm", "--format", "png"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::line_count(r.stderr_text), 1) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("--format"), std::string::npos) << r.stderr_text;
}

TEST_F(OmniInspectCli, WrongFormatForTheFileIsRejected) {
  const fs::path table = dir / "table.bsgm";
  write_file_atomic(table, documented_ground_map());
  const test::CliResult r = inspect({table.string(), "--format", "iris-px2cm"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.stderr_text.find("expected 2304000 bytes"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(test::line_count(r.stderr_text), 1) << r.stderr_text;
}

}  // namespace
}  // namespace ballsight
