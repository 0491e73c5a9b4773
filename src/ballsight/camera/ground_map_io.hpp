#pragma once
// GroundMap files: a versioned little-endian binary format with a 144-byte header (magic,
// version, image size, image centre, valid range, units, method, CRC-32) followed by one
// {x_cm, y_cm} float32 pair per pixel. Byte-by-byte description: docs/lut-format.md.

#include <cstdint>
#include <filesystem>
#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "ballsight/camera/ground_map.hpp"

namespace ballsight {

inline constexpr std::string_view kGroundMapMagic = "BSGRDMAP";
inline constexpr std::uint32_t kGroundMapVersion = 1;
inline constexpr std::size_t kGroundMapHeaderBytes = 144;

/// The file's bytes for `map`.
std::string ground_map_bytes(const GroundMap& map);
/// Writes `map` atomically; throws InputError naming the path on failure.
void save_ground_map(const std::filesystem::path& path, const GroundMap& map);

/// Reads a table. Throws InputError naming the file and the problem when it is missing, empty,
/// not a ground map, of an unsupported version, truncated, corrupt (checksum mismatch), or when
/// `expected_image_size` is given and differs from the table's.
GroundMap load_ground_map(const std::filesystem::path& path,
                          std::optional<cv::Size> expected_image_size = std::nullopt);

/// The same for a table's bytes (an upload); errors name `where`.
GroundMap parse_ground_map(std::string_view bytes, const std::string& where,
                           std::optional<cv::Size> expected_image_size = std::nullopt);

/// Whether `bytes` begin with the ground map magic (format detection).
bool has_ground_map_magic(std::string_view bytes);

}  // namespace ballsight
