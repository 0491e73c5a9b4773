#include "ballsight/camera/ground_map_io.hpp"

#include <cstdio>
#include <string>

#include "ballsight/core/checksum.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/little_endian.hpp"

namespace ballsight {

namespace {

constexpr std::uint32_t kUnitsCentimetres = 1;  // robot-local x forward, y left, in cm
constexpr std::uint32_t kCellFloat32Pair = 1;   // {x_cm, y_cm} as two float32
constexpr std::size_t kMethodBytes = 64;
constexpr std::size_t kChecksumOffset = 140;
constexpr std::size_t kCellBytes = 8;

/// CRC-32 of the whole file except the checksum field itself.
std::uint32_t file_checksum(std::string_view file) {
  return crc32(crc32(0, file.substr(0, kChecksumOffset)), file.substr(kGroundMapHeaderBytes));
}

std::string hex32(std::uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", v);
  return text;
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

std::uint64_t payload_bytes(const GroundMapInfo& info) {
  return std::uint64_t{static_cast<std::uint64_t>(info.width)} *
         static_cast<std::uint64_t>(info.height) * kCellBytes;
}

}  // namespace

bool has_ground_map_magic(std::string_view bytes) {
  return bytes.substr(0, kGroundMapMagic.size()) == kGroundMapMagic;
}

std::string ground_map_bytes(const GroundMap& map) {
  const GroundMapInfo& info = map.info();
  std::string file;
  file.reserve(kGroundMapHeaderBytes + payload_bytes(info));
  LittleEndianWriter out(file);
  out.padded(kGroundMapMagic, kGroundMapMagic.size());
  out.u32(kGroundMapVersion);
  out.u32(static_cast<std::uint32_t>(kGroundMapHeaderBytes));
  out.u32(static_cast<std::uint32_t>(info.width));
  out.u32(static_cast<std::uint32_t>(info.height));
  out.f64(info.image_center_px.x());
  out.f64(info.image_center_px.y());
  out.f64(info.min_radius_px);
  out.f64(info.max_radius_px);
  out.u32(kUnitsCentimetres);
  out.u32(kCellFloat32Pair);
  out.u64(payload_bytes(info));
  out.padded(info.method, kMethodBytes);
  out.u32(static_cast<std::uint32_t>(std::lround(info.viewpoint_height_cm * 10.0)));  // mm
  out.u32(0);  // checksum, filled in below
  for (const GroundCell& cell : map.cells()) {
    out.f32(cell.x_cm);
    out.f32(cell.y_cm);
  }
  std::string checksum;
  LittleEndianWriter(checksum).u32(file_checksum(file));
  file.replace(kChecksumOffset, checksum.size(), checksum);
  return file;
}

void save_ground_map(const std::filesystem::path& path, const GroundMap& map) {
  write_file_atomic(path, ground_map_bytes(map));
}

GroundMap load_ground_map(const std::filesystem::path& path,
                          std::optional<cv::Size> expected_image_size) {
  return parse_ground_map(read_file(path), path.string(), expected_image_size);
}

GroundMap parse_ground_map(std::string_view file, const std::string& where,
                           std::optional<cv::Size> expected_image_size) {
  require(!file.empty(), where, "empty file (expected a ballsight ground map)");
  const std::string_view magic_part = file.substr(0, std::min(file.size(), kGroundMapMagic.size()));
  require(kGroundMapMagic.starts_with(magic_part), where,
          "not a ballsight ground map (bad magic; iris tables need --format iris-px2cm)");
  require(file.size() >= kGroundMapHeaderBytes, where,
          "truncated: expected at least " + std::to_string(kGroundMapHeaderBytes) +
              " bytes (the header), got " + std::to_string(file.size()));

  LittleEndianReader in(file, kGroundMapMagic.size());
  const std::uint32_t version = in.u32();
  require(version == kGroundMapVersion, where,
          "version " + std::to_string(version) + " not supported (expected " +
              std::to_string(kGroundMapVersion) + ")");
  const std::uint32_t header_bytes = in.u32();
  const std::uint32_t width = in.u32();
  const std::uint32_t height = in.u32();
  GroundMapInfo info;
  info.image_center_px.x() = in.f64();
  info.image_center_px.y() = in.f64();
  info.min_radius_px = in.f64();
  info.max_radius_px = in.f64();
  const std::uint32_t units = in.u32();
  const std::uint32_t cell_format = in.u32();
  const std::uint64_t payload = in.u64();
  info.method = in.padded(kMethodBytes);
  info.viewpoint_height_cm = in.u32() / 10.0;  // stored in mm
  const std::uint32_t stored_checksum = in.u32();

  // The payload size is stored twice (image size and byte count): a damaged size field shows
  // as a mismatch here rather than as a misleading "truncated".
  const bool sizes_agree = header_bytes == kGroundMapHeaderBytes && width <= 8192 &&
                           height <= 8192 && payload == std::uint64_t{width} * height * kCellBytes;
  require(sizes_agree, where,
          "corrupt header (header size " + std::to_string(header_bytes) + ", image size " +
              std::to_string(width) + "x" + std::to_string(height) + " and payload size " +
              std::to_string(payload) + " disagree)");
  const std::uint64_t expected_bytes = kGroundMapHeaderBytes + payload;
  require(file.size() >= expected_bytes, where,
          "truncated: expected " + std::to_string(expected_bytes) + " bytes, got " +
              std::to_string(file.size()));
  require(file.size() == expected_bytes, where,
          "trailing data: expected " + std::to_string(expected_bytes) + " bytes, got " +
              std::to_string(file.size()));
  const std::uint32_t computed = file_checksum(file);
  require(stored_checksum == computed, where,
          "checksum mismatch (stored " + hex32(stored_checksum) + ", computed " + hex32(computed) +
              "): the file is corrupt");

  require(units == kUnitsCentimetres, where,
          "units code " + std::to_string(units) + " not supported (expected 1 = cm)");
  require(cell_format == kCellFloat32Pair, where,
          "cell format " + std::to_string(cell_format) + " not supported (expected 1)");
  info.width = static_cast<int>(width);
  info.height = static_cast<int>(height);
  try {
    info.validate();
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  if (expected_image_size) {
    require(expected_image_size->width == info.width && expected_image_size->height == info.height,
            where,
            "image size " + size_text(info.width, info.height) + " does not match " +
                size_text(expected_image_size->width, expected_image_size->height));
  }

  std::vector<GroundCell> cells(static_cast<std::size_t>(info.width) * info.height);
  for (GroundCell& cell : cells) {
    cell.x_cm = in.f32();
    cell.y_cm = in.f32();
  }
  return GroundMap(std::move(info), std::move(cells));
}

}  // namespace ballsight
