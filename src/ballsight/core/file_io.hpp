#pragma once
// File helpers: whole-file reads and atomic writes (temporary file in the same folder, then
// rename), so an existing output is never left half-written.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ballsight {

/// Files larger than this are refused before they are read: every input ballsight reads (tables,
/// sample CSVs, YAML, JSON, images) is read whole, and 1 GiB is far beyond any real one.
inline constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
/// Text documents parsed whole (YAML, JSON, CSV) take up to about 16 times their bytes once
/// parsed; above this they are refused, which keeps the parsed form within 1 GiB.
inline constexpr std::uintmax_t kMaxDocumentBytes = std::uintmax_t{64} << 20;

/// Reads a whole file as bytes; throws InputError naming the path when it cannot be read, or when
/// it holds more than `max_bytes` (checked before anything is allocated for a regular file, as it
/// is read for a pipe or a device).
std::string read_file(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxFileBytes);

/// Writes `bytes` to `path` atomically; throws InputError naming the path on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// Creates `dir` (and parents) if missing; throws InputError when it is not a usable folder.
void ensure_directory(const std::filesystem::path& dir);

}  // namespace ballsight
