#pragma once
// File helpers: whole-file reads and atomic writes (temporary file in the same folder, then
// rename), so an existing output is never left half-written.

#include <filesystem>
#include <string>
#include <string_view>

namespace ballsight {

/// Reads a whole file as bytes; throws InputError naming the path when it cannot be read.
std::string read_file(const std::filesystem::path& path);

/// Writes `bytes` to `path` atomically; throws InputError naming the path on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// Creates `dir` (and parents) if missing; throws InputError when it is not a usable folder.
void ensure_directory(const std::filesystem::path& dir);

}  // namespace ballsight
