#pragma once
// The compressions MCAP names for a chunk's records (https://mcap.dev/spec/registry, "Well-known
// compression formats"): "zstd" (a Zstandard frame) and "lz4" (an LZ4 frame), through Debian's
// libzstd and liblz4; "" is none.

#include <cstdint>
#include <string>
#include <string_view>

namespace ballsight::mcap {

enum class Compression { none, zstd, lz4 };

/// The name written into the file ("", "zstd", "lz4").
std::string compression_name(Compression compression);
/// The compression named `name` on the command line ("none", "zstd", "lz4"); throws InputError
/// naming `where` otherwise.
Compression parse_compression(std::string_view name, const std::string& where);

/// `bytes` compressed (zstd at level 1: a recorder's speed matters more than the last percent).
std::string compress(Compression compression, std::string_view bytes);

/// A chunk's records decompressed to exactly `size` bytes; `name` is the chunk's compression
/// field. Throws InputError naming `where` for an unknown compression, data that does not
/// decompress, or a size other than `size`.
std::string decompress(std::string_view name, std::string_view bytes, std::uint64_t size,
                       const std::string& where);

}  // namespace ballsight::mcap
