#include "ballsight/record/compression.hpp"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <memory>

#include "ballsight/core/error.hpp"

namespace ballsight::mcap {
namespace {

/// The output buffer of a decompression that claims `size` bytes: it starts near what the input
/// could plausibly hold and grows as bytes really come out, so that a file that claims a huge
/// chunk in a few bytes costs no more memory than it decompresses to.
class GrowingOutput {
 public:
  GrowingOutput(std::uint64_t size, std::size_t input_bytes)
      : size_(size),
        out_(std::min<std::uint64_t>(size, 8 * std::uint64_t{input_bytes} + 65536), '\0') {}
  /// Room after `used` bytes; grows (doubling, up to the claimed size) when there is none.
  char* room(std::size_t used, std::size_t& available) {
    if (used == out_.size() && out_.size() < size_) {
      out_.resize(std::min<std::uint64_t>(size_, 2 * std::uint64_t{out_.size()}));
    }
    available = out_.size() - used;
    return out_.data() + used;
  }
  std::string take(std::size_t used) {
    out_.resize(used);
    return std::move(out_);
  }

 private:
  std::uint64_t size_;
  std::string out_;
};

std::string zstd_decompress(std::string_view bytes, std::uint64_t size, const std::string& where) {
  const std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> context(ZSTD_createDCtx(),
                                                                     ZSTD_freeDCtx);
  require(context != nullptr, where, "no zstd decompression context");
  GrowingOutput out(size, bytes.size());
  ZSTD_inBuffer in{bytes.data(), bytes.size(), 0};
  std::size_t used = 0;
  std::size_t hint = 1;
  while (hint != 0) {
    std::size_t available = 0;
    char* room = out.room(used, available);
    ZSTD_outBuffer chunk{room, available, 0};
    const std::size_t in_before = in.pos;
    hint = ZSTD_decompressStream(context.get(), &chunk, &in);
    require(!ZSTD_isError(hint), where,
            std::string("the zstd data does not decompress: ") + ZSTD_getErrorName(hint));
    used += chunk.pos;
    if (hint != 0 && chunk.pos == 0 && in.pos == in_before) {  // no progress
      require(available != 0, where,
              "the zstd data holds more than " + std::to_string(size) + " bytes");
      throw InputError(where + ": the zstd frame is cut short");
    }
  }
  require(in.pos == in.size, where, "bytes follow the zstd frame");
  require(used == size, where,
          "the zstd data holds " + std::to_string(used) + " bytes, not " + std::to_string(size));
  return out.take(used);
}

std::string lz4_decompress(std::string_view bytes, std::uint64_t size, const std::string& where) {
  LZ4F_dctx* raw = nullptr;
  require(!LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION)), where,
          "no LZ4 decompression context");
  const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> context(
      raw, LZ4F_freeDecompressionContext);
  GrowingOutput out(size, bytes.size());
  std::size_t in_at = 0;
  std::size_t used = 0;
  std::size_t hint = 1;
  while (hint != 0 && in_at < bytes.size()) {
    std::size_t available = 0;
    char* room = out.room(used, available);
    std::size_t in_left = bytes.size() - in_at;
    hint =
        LZ4F_decompress(context.get(), room, &available, bytes.data() + in_at, &in_left, nullptr);
    require(!LZ4F_isError(hint), where,
            std::string("the lz4 data does not decompress: ") + LZ4F_getErrorName(hint));
    // No progress: the frame needs more room than the size it claims.
    require(available != 0 || in_left != 0 || hint == 0, where,
            "the lz4 data holds more than " + std::to_string(size) + " bytes");
    in_at += in_left;
    used += available;
  }
  require(hint == 0, where, "the lz4 frame is cut short");
  require(in_at == bytes.size(), where, "bytes follow the lz4 frame");
  require(used == size, where,
          "the lz4 data holds " + std::to_string(used) + " bytes, not " + std::to_string(size));
  return out.take(used);
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
