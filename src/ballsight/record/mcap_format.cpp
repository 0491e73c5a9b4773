#include "ballsight/record/mcap_format.hpp"

#include <algorithm>
#include <array>

#include "ballsight/core/checksum.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/little_endian.hpp"

namespace ballsight::mcap {
namespace {

/// Writes a record's fields in the file's layout.
class FieldWriter {
 public:
  explicit FieldWriter(std::string& out) : out_(out), le_(out) {}
  void operator()(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void operator()(std::uint16_t v) { le_.u16(v); }
  void operator()(std::uint32_t v) { le_.u32(v); }
  void operator()(std::uint64_t v) { le_.u64(v); }
  void operator()(const std::string& s) {
    le_.u32(static_cast<std::uint32_t>(s.size()));
    out_.append(s);
  }
  void operator()(const RestBytes& b) { out_.append(b.bytes); }
  void operator()(const LongBytes& b) {
    le_.u64(b.bytes.size());
    out_.append(b.bytes);
  }
  /// Maps and arrays: a u32 byte length, then the entries.
  template <class K, class V, class Container>
  void entries(const Container& container) {
    const std::size_t length_at = out_.size();
    le_.u32(0);
    for (const auto& [key, value] : container) (*this)(K(key)), (*this)(V(value));
    const auto length = static_cast<std::uint32_t>(out_.size() - length_at - 4);
    std::string length_bytes;
    LittleEndianWriter(length_bytes).u32(length);
    out_.replace(length_at, 4, length_bytes);
  }
  void operator()(const StringMap& m) { entries<std::string, std::string>(m); }
  void operator()(const ChannelCounts& m) { entries<std::uint16_t, std::uint64_t>(m); }
  void operator()(const TimeOffsets& v) { entries<std::uint64_t, std::uint64_t>(v); }

 private:
  std::string& out_;
  LittleEndianWriter le_;
};

/// Reads a record's fields, refusing any that runs past the record's end.
class FieldReader {
 public:
  FieldReader(std::string_view bytes, std::string where)
      : bytes_(bytes), where_(std::move(where)) {}
  void operator()(std::uint8_t& v) { v = static_cast<std::uint8_t>(take(1)[0]); }
  void operator()(std::uint16_t& v) { v = LittleEndianReader(take(2)).u16(); }
  void operator()(std::uint32_t& v) { v = LittleEndianReader(take(4)).u32(); }
  void operator()(std::uint64_t& v) { v = LittleEndianReader(take(8)).u64(); }
  void operator()(std::string& s) {
    std::uint32_t length = 0;
    (*this)(length);
    s = std::string(take(length));
  }
  void operator()(RestBytes& b) { b.bytes = std::string(take(bytes_.size() - offset_)); }
  void operator()(LongBytes& b) {
    std::uint64_t length = 0;
    (*this)(length);
    b.bytes = std::string(take(length));
  }
  template <class K, class V, class Container>
  void entries(Container& container) {
    std::uint32_t length = 0;
    (*this)(length);
    FieldReader inner(take(length), where_);
    while (!inner.done()) {
      K key{};
      V value{};
      inner(key), inner(value);
      container.insert(container.end(), {key, value});
    }
  }
  void operator()(StringMap& m) { entries<std::string, std::string>(m); }
  void operator()(ChannelCounts& m) { entries<std::uint16_t, std::uint64_t>(m); }
  void operator()(TimeOffsets& v) { entries<std::uint64_t, std::uint64_t>(v); }

  bool done() const { return offset_ == bytes_.size(); }
  std::size_t offset() const { return offset_; }

 private:
  std::string_view take(std::uint64_t n) {
    require(n <= bytes_.size() - offset_, where_,
            "a field of " + std::to_string(n) + " bytes at its byte " + std::to_string(offset_) +
                " runs past the record's end (" + std::to_string(bytes_.size()) + " bytes)");
    const std::string_view field = bytes_.substr(offset_, n);
    offset_ += n;
    return field;
  }
  std::string_view bytes_;
  std::string where_;
  std::size_t offset_ = 0;
};

template <class R>
std::string content_of(const R& record) {
  std::string content;
  FieldWriter writer(content);
  R::fields(writer, record);
  if constexpr (std::is_same_v<R, Attachment>) {
    LittleEndianWriter(content).u32(crc32(0, content));
  }
  return content;
}

}  // namespace

template <class R>
void append_record(std::string& out, const R& record) {
  const std::string content = content_of(record);
  out.push_back(static_cast<char>(R::op));
  LittleEndianWriter(out).u64(content.size());
  out.append(content);
}

template <class R>
R parse_record(std::string_view content, const std::string& where) {
  const std::string context = where + ": " + op_name(R::op) + " record";
  R record;
  FieldReader reader(content, context);
  R::fields(reader, record);
  if constexpr (std::is_same_v<R, Attachment>) {
    const std::size_t covered = reader.offset();
    std::uint32_t crc = 0;
    reader(crc);
    require(crc == 0 || crc == crc32(0, content.substr(0, covered)), context,
            "the CRC does not match the attachment \"" + record.name + "\"");
  }
  return record;
}

void Statistics::count(const Message& message) {
  if (message_count == 0) message_start_time = message_end_time = message.log_time;
  ++message_count;
  ++channel_message_counts[message.channel_id];
  message_start_time = std::min(message_start_time, message.log_time);
  message_end_time = std::max(message_end_time, message.log_time);
}

bool next_record(std::string_view bytes, std::uint64_t& offset, RawRecord& record) {
  constexpr std::uint64_t kPrefix = 9;
  if (offset > bytes.size() || bytes.size() - offset < kPrefix) return false;
  const std::uint64_t length = LittleEndianReader(bytes.substr(offset + 1, 8)).u64();
  if (length > bytes.size() - offset - kPrefix) return false;
  record.op = static_cast<Op>(static_cast<std::uint8_t>(bytes[offset]));
  record.content = bytes.substr(offset + kPrefix, length);
  record.offset = offset;
  offset += kPrefix + length;
  return true;
}

std::string op_name(Op op) {
  static constexpr std::array<const char*, 16> names = {
      "opcode 0x00",      "header",     "footer",        "schema",         "channel",
      "message",          "chunk",      "message index", "chunk index",    "attachment",
      "attachment index", "statistics", "metadata",      "metadata index", "summary offset",
      "data end"};
  const auto code = static_cast<std::uint8_t>(op);
  if (code < names.size()) return names[code];
  constexpr char hex[] = "0123456789abcdef";
  return std::string("opcode 0x") + hex[code >> 4] + hex[code & 15];
}

#define BALLSIGHT_MCAP_RECORD(R)                          \
  template void append_record<R>(std::string&, const R&); \
  template R parse_record<R>(std::string_view, const std::string&);
BALLSIGHT_MCAP_RECORD(Header)
BALLSIGHT_MCAP_RECORD(Footer)
BALLSIGHT_MCAP_RECORD(Schema)
BALLSIGHT_MCAP_RECORD(Channel)
BALLSIGHT_MCAP_RECORD(Message)
BALLSIGHT_MCAP_RECORD(Chunk)
BALLSIGHT_MCAP_RECORD(MessageIndex)
BALLSIGHT_MCAP_RECORD(ChunkIndex)
BALLSIGHT_MCAP_RECORD(Attachment)
BALLSIGHT_MCAP_RECORD(AttachmentIndex)
BALLSIGHT_MCAP_RECORD(Statistics)
BALLSIGHT_MCAP_RECORD(Metadata)
BALLSIGHT_MCAP_RECORD(MetadataIndex)
BALLSIGHT_MCAP_RECORD(SummaryOffset)
BALLSIGHT_MCAP_RECORD(DataEnd)
#undef BALLSIGHT_MCAP_RECORD

}  // namespace ballsight::mcap
