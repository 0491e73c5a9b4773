#include "ballsight/camera/ground_map_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/little_endian.hpp"
#include "temp_dir.hpp"

namespace ballsight {
namespace {

namespace fs = std::filesystem;

// A small table with a recognisable pattern and some invalid cells.
GroundMap pattern_map(int width, int height) {
  GroundMapInfo info;
  info.width = width;
  info.height = height;
  info.image_center_px = {0.5 * (width - 1) + 0.25, 0.5 * (height - 1) - 0.75};
  info.min_radius_px = 1.5;
  info.max_radius_px = 0.5 * width;
  info.method = "pattern";
  std::vector<GroundCell> cells(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i % 7 == 3) continue;  // stays NaN
    cells[i] = {static_cast<float>(i) * 0.5f - 17.25f, -static_cast<float>(i) / 3.0f};
  }
  return GroundMap(info, std::move(cells));
}

class GroundMapFile : public ::testing::Test {
 protected:
  /// Loads `path` and returns the InputError message ("" when it loads).
  std::string load_error(std::optional<cv::Size> expected = std::nullopt) const {
    try {
      load_ground_map(path, expected);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  void expect_error(const std::string& problem,
                    std::optional<cv::Size> expected = std::nullopt) const {
    const std::string message = load_error(expected);
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
  }
  std::string bytes() const { return read_file(path); }
  void set_bytes(const std::string& b) const { write_file_atomic(path, b); }

  test::TempDir dir;
  fs::path path = dir / "table.bsgm";
};

TEST_F(GroundMapFile, KeepsTheViewpointHeightToTheMillimetre) {
  GroundMap map = pattern_map(9, 7);
  GroundMapInfo info = map.info();
  info.viewpoint_height_cm = 61.37;
  save_ground_map(path, GroundMap(info, {map.cells().begin(), map.cells().end()}));
  EXPECT_DOUBLE_EQ(load_ground_map(path).info().viewpoint_height_cm, 61.4);
}

TEST_F(GroundMapFile, RoundTripsBitForBit) {
  const GroundMap map = pattern_map(23, 17);
  save_ground_map(path, map);
  EXPECT_EQ(fs::file_size(path), kGroundMapHeaderBytes + 23u * 17u * 8u);
  const GroundMap loaded = load_ground_map(path, cv::Size(23, 17));
  EXPECT_EQ(loaded.info().width, 23);
  EXPECT_EQ(loaded.info().height, 17);
  EXPECT_EQ(loaded.info().image_center_px, map.info().image_center_px);
  EXPECT_EQ(loaded.info().min_radius_px, map.info().min_radius_px);
  EXPECT_EQ(loaded.info().max_radius_px, map.info().max_radius_px);
  EXPECT_EQ(loaded.info().method, "pattern");
  EXPECT_EQ(loaded.info().viewpoint_height_cm, 0.0);
  ASSERT_EQ(loaded.cells().size(), map.cells().size());
  EXPECT_EQ(std::memcmp(loaded.cells().data(), map.cells().data(), map.cells().size_bytes()), 0);
  // Saving the loaded table gives the same file.
  const std::string first = bytes();
  save_ground_map(path, loaded);
  EXPECT_EQ(bytes(), first);
}

TEST_F(GroundMapFile, HeaderFieldsSitAtTheirDocumentedOffsets) {
  save_ground_map(path, pattern_map(23, 17));
  const std::string b = bytes();
  EXPECT_EQ(b.substr(0, 8), "BSGRDMAP");
  LittleEndianReader in(b, 8);
  EXPECT_EQ(in.u32(), 1u);              // 8: version
  EXPECT_EQ(in.u32(), 144u);            // 12: header bytes
  EXPECT_EQ(in.u32(), 23u);             // 16: width
  EXPECT_EQ(in.u32(), 17u);             // 20: height
  EXPECT_EQ(in.f64(), 11.25);           // 24: centre x
  EXPECT_EQ(in.f64(), 7.25);            // 32: centre y
  EXPECT_EQ(in.f64(), 1.5);             // 40: min radius
  EXPECT_EQ(in.f64(), 11.5);            // 48: max radius
  EXPECT_EQ(in.u32(), 1u);              // 56: units = cm
  EXPECT_EQ(in.u32(), 1u);              // 60: cell format = float32 pair
  EXPECT_EQ(in.u64(), 23u * 17u * 8u);  // 64: payload bytes
  EXPECT_EQ(in.padded(64), "pattern");  // 72: method
  EXPECT_EQ(in.u32(), 0u);              // 136: viewpoint height (unknown)
  in.u32();                             // 140: checksum
  EXPECT_EQ(in.f32(), -17.25f);         // 144: cell (0, 0).x_cm
  EXPECT_EQ(in.f32(), -0.0f);           // 148: cell (0, 0).y_cm
}

TEST_F(GroundMapFile, TruncatedFileIsRejected) {
  save_ground_map(path, pattern_map(23, 17));
  const std::string full = bytes();
  set_bytes(full.substr(0, full.size() - 5));
  expect_error("truncated: expected " + std::to_string(full.size()) + " bytes, got " +
               std::to_string(full.size() - 5));
  set_bytes(full.substr(0, 100));
  expect_error("truncated: expected at least 144 bytes (the header), got 100");
}

TEST_F(GroundMapFile, FlippedByteIsACorruptFile) {
  save_ground_map(path, pattern_map(23, 17));
  const std::string good = bytes();
  for (std::size_t offset :
       {std::size_t{30}, std::size_t{100}, std::size_t{144}, good.size() / 2, good.size() - 1}) {
    std::string bad = good;
    bad[offset] = static_cast<char>(bad[offset] ^ 0x10);
    set_bytes(bad);
    SCOPED_TRACE("flipped byte " + std::to_string(offset));
    expect_error("checksum mismatch");
  }
  std::string bad = good;
  bad[16] = static_cast<char>(bad[16] ^ 0x01);  // width 23 -> 22
  set_bytes(bad);
  expect_error("corrupt header (header size 144, image size 22x17 and payload size 3128 disagree)");
}

TEST_F(GroundMapFile, WrongVersionIsRejected) {
  save_ground_map(path, pattern_map(23, 17));
  std::string b = bytes();
  b[8] = 7;
  set_bytes(b);
  expect_error("version 7 not supported (expected 1)");
}

TEST_F(GroundMapFile, WrongImageSizeIsRejected) {
  GroundMapInfo info;
  info.width = 800;
  info.height = 600;
  save_ground_map(path, GroundMap(info, std::vector<GroundCell>(800 * 600)));
  expect_error("image size 800x600 does not match 640x480", cv::Size(640, 480));
  EXPECT_EQ(load_error(cv::Size(800, 600)), "");
}

TEST_F(GroundMapFile, EmptyMissingAndForeignFilesAreRejected) {
  set_bytes("");
  expect_error("empty file");
  fs::remove(path);
  expect_error("cannot open");
  set_bytes(std::string(2304000, '\0'));  // an iris table, say
  expect_error("not a ballsight ground map");
  save_ground_map(path, pattern_map(5, 5));
  set_bytes(bytes() + "x");
  expect_error("trailing data");
}

TEST_F(GroundMapFile, SavingIntoAMissingFolderNamesThePath) {
  const fs::path nowhere = dir / "missing" / "table.bsgm";
  try {
    save_ground_map(nowhere, pattern_map(5, 5));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(nowhere.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ballsight
