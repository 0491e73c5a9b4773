#include "ballsight/record/compression.hpp"

#include <lz4frame.h>
#include <zstd.h>

#include <memory>

#include "ballsight/core/error.hpp"

namespace ballsight::mcap {
namespace {

std::string zstd_decompress(std::string_view bytes, std::uint64_t size, const std::string& where) {
  std::string out(size, '\0');
  const std::size_t got = ZSTD_decompress(out.data(), out.size(), bytes.data(), bytes.size());
  require(!ZSTD_isError(got), where,
          std::string("the zstd data does not decompress: ") + ZSTD_getErrorName(got));
  require(got == size, where,
          "the zstd data holds " + std::to_string(got) + " bytes, not " + std::to_string(size));
  return out;
}

std::string lz4_decompress(std::string_view bytes, std::uint64_t size, const std::string& where) {
  LZ4F_dctx* raw = nullptr;
  require(!LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION)), where,
          "no LZ4 decompression context");
  const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> context(
      raw, LZ4F_freeDecompressionContext);
  std::string out(size, '\0');
  std::size_t in_at = 0;
  std::size_t out_at = 0;
  std::size_t hint = 1;
  while (hint != 0 && in_at < bytes.size()) {
    std::size_t out_room = out.size() - out_at;
    std::size_t in_left = bytes.size() - in_at;
    hint = LZ4F_decompress(context.get(), out.data() + out_at, &out_room, bytes.data() + in_at,
                           &in_left, nullptr);
    require(!LZ4F_isError(hint), where,
            std::string("the lz4 data does not decompress: ") + LZ4F_getErrorName(hint));
    require(out_room != 0 || in_left != 0 || hint == 0, where,
            "the lz4 data holds more than " + std::to_string(size) + " bytes");
    in_at += in_left;
    out_at += out_room;
  }
  require(hint == 0, where, "the lz4 frame is cut short");
  require(out_at == size, where,
          "the lz4 data holds " + std::to_string(out_at) + " bytes, not " + std::to_string(size));
  return out;
}

}  // namespace

std::string compression_name(Compression compression) {
  switch (compression) {
    case Compression::zstd:
      return "zstd";
    case Compression::lz4:
      return "lz4";
    case Compression::none:
      break;
  }
  return "";
}

Compression parse_compression(std::string_view name, const std::string& where) {
  if (name == "none") return Compression::none;
  if (name == "zstd") return Compression::zstd;
  if (name == "lz4") return Compression::lz4;
  throw InputError(where + ": unknown compression \"" + std::string(name) +
                   "\" (expected none, zstd or lz4)");
}

std::string compress(Compression compression, std::string_view bytes) {
  std::string out;
  if (compression == Compression::zstd) {
    out.resize(ZSTD_compressBound(bytes.size()));
    const std::size_t size = ZSTD_compress(out.data(), out.size(), bytes.data(), bytes.size(), 1);
    if (ZSTD_isError(size)) throw std::runtime_error(ZSTD_getErrorName(size));
    out.resize(size);
  } else if (compression == Compression::lz4) {
    out.resize(LZ4F_compressFrameBound(bytes.size(), nullptr));
    const std::size_t size =
        LZ4F_compressFrame(out.data(), out.size(), bytes.data(), bytes.size(), nullptr);
    if (LZ4F_isError(size)) throw std::runtime_error(LZ4F_getErrorName(size));
    out.resize(size);
  } else {
    out = bytes;
  }
  return out;
}

std::string decompress(std::string_view name, std::string_view bytes, std::uint64_t size,
                       const std::string& where) {
  if (name.empty()) {
    require(bytes.size() == size, where,
            "the uncompressed records hold " + std::to_string(bytes.size()) + " bytes, not " +
                std::to_string(size));
    return std::string(bytes);
  }
  if (name == "zstd") return zstd_decompress(bytes, size, where);
  if (name == "lz4") return lz4_decompress(bytes, size, where);
  throw InputError(where + ": unknown compression \"" + std::string(name) +
                   "\" (ballsight reads zstd, lz4 and none)");
}

}  // namespace ballsight::mcap
