#pragma once
// The records of an MCAP file (https://mcap.dev/spec, "MCAP Format Specification", major version
// 0) and their byte layout: every record is <opcode u8><content length u64><content>, integers
// little-endian, strings and maps u32-length-prefixed. Each record type lists its fields once
// (`fields`), and the same list writes and reads it, so the two cannot disagree.

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ballsight::mcap {

/// The eight bytes that open and close every MCAP file.
inline constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

enum class Op : std::uint8_t {
  header = 0x01,
  footer = 0x02,
  schema = 0x03,
  channel = 0x04,
  message = 0x05,
  chunk = 0x06,
  message_index = 0x07,
  chunk_index = 0x08,
  attachment = 0x09,
  attachment_index = 0x0A,
  statistics = 0x0B,
  metadata = 0x0C,
  metadata_index = 0x0D,
  summary_offset = 0x0E,
  data_end = 0x0F,
};

using StringMap = std::map<std::string, std::string>;
using ChannelCounts = std::map<std::uint16_t, std::uint64_t>;  // also channel -> offset
/// A Message Index's entries: (log time, offset in the chunk's uncompressed records).
using TimeOffsets = std::vector<std::pair<std::uint64_t, std::uint64_t>>;

/// Bytes that fill the rest of a record (a Message's data) or carry a u64 length (a Chunk's
/// records, an Attachment's data), where a plain std::string field carries a u32 length.
struct RestBytes {
  std::string bytes;
  bool operator==(const RestBytes&) const = default;
};
struct LongBytes {
  std::string bytes;
  bool operator==(const LongBytes&) const = default;
};

struct Header {
  static constexpr Op op = Op::header;
  std::string profile;
  std::string library;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.profile), f(r.library);
  }
};

struct Footer {
  static constexpr Op op = Op::footer;
  std::uint64_t summary_start = 0;
  std::uint64_t summary_offset_start = 0;
  std::uint32_t summary_crc = 0;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.summary_start), f(r.summary_offset_start), f(r.summary_crc);
  }
};

struct Schema {
  static constexpr Op op = Op::schema;
  std::uint16_t id = 0;
  std::string name;
  std::string encoding;  // "jsonschema", or "" for none
  std::string data;
  bool operator==(const Schema&) const = default;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.id), f(r.name), f(r.encoding), f(r.data);
  }
};

struct Channel {
  static constexpr Op op = Op::channel;
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;  // "json"
  StringMap metadata;
  bool operator==(const Channel&) const = default;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.id), f(r.schema_id), f(r.topic), f(r.message_encoding), f(r.metadata);
  }
};

struct Message {
  static constexpr Op op = Op::message;
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;  // ns since the Unix epoch in ballsight's files
  std::uint64_t publish_time = 0;
  RestBytes data;
  bool operator==(const Message&) const = default;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.channel_id), f(r.sequence), f(r.log_time), f(r.publish_time), f(r.data);
  }
};

struct Chunk {
  static constexpr Op op = Op::chunk;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::uint64_t uncompressed_size = 0;
  std::uint32_t uncompressed_crc = 0;
  std::string compression;  // "", "zstd" or "lz4"
  LongBytes records;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.message_start_time), f(r.message_end_time), f(r.uncompressed_size), f(r.uncompressed_crc),
        f(r.compression), f(r.records);
  }
};

struct MessageIndex {
  static constexpr Op op = Op::message_index;
  std::uint16_t channel_id = 0;
  TimeOffsets records;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.channel_id), f(r.records);
  }
};

struct ChunkIndex {
  static constexpr Op op = Op::chunk_index;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::uint64_t chunk_start_offset = 0;
  std::uint64_t chunk_length = 0;
  ChannelCounts message_index_offsets;
  std::uint64_t message_index_length = 0;
  std::string compression;
  std::uint64_t compressed_size = 0;
  std::uint64_t uncompressed_size = 0;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.message_start_time), f(r.message_end_time), f(r.chunk_start_offset), f(r.chunk_length),
        f(r.message_index_offsets), f(r.message_index_length), f(r.compression),
        f(r.compressed_size), f(r.uncompressed_size);
  }
};

/// An attachment; its CRC (of the fields before it) is written and checked by the codec.
struct Attachment {
  static constexpr Op op = Op::attachment;
  std::uint64_t log_time = 0;
  std::uint64_t create_time = 0;
  std::string name;
  std::string media_type;
  LongBytes data;
  bool operator==(const Attachment&) const = default;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.log_time), f(r.create_time), f(r.name), f(r.media_type), f(r.data);
  }
};

struct AttachmentIndex {
  static constexpr Op op = Op::attachment_index;
  std::uint64_t offset = 0;
  std::uint64_t length = 0;
  std::uint64_t log_time = 0;
  std::uint64_t create_time = 0;
  std::uint64_t data_size = 0;
  std::string name;
  std::string media_type;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.offset), f(r.length), f(r.log_time), f(r.create_time), f(r.data_size), f(r.name),
        f(r.media_type);
  }
};

struct Statistics {
  static constexpr Op op = Op::statistics;
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0;
  std::uint32_t attachment_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  ChannelCounts channel_message_counts;
  bool operator==(const Statistics&) const = default;
  /// Counts `message` in: its channel's count, the total and the time span.
  void count(const Message& message);
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.message_count), f(r.schema_count), f(r.channel_count), f(r.attachment_count),
        f(r.metadata_count), f(r.chunk_count), f(r.message_start_time), f(r.message_end_time),
        f(r.channel_message_counts);
  }
};

struct Metadata {
  static constexpr Op op = Op::metadata;
  std::string name;
  StringMap metadata;
  bool operator==(const Metadata&) const = default;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.name), f(r.metadata);
  }
};

struct MetadataIndex {
  static constexpr Op op = Op::metadata_index;
  std::uint64_t offset = 0;
  std::uint64_t length = 0;
  std::string name;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.offset), f(r.length), f(r.name);
  }
};

struct SummaryOffset {
  static constexpr Op op = Op::summary_offset;
  std::uint8_t group_opcode = 0;
  std::uint64_t group_start = 0;
  std::uint64_t group_length = 0;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.group_opcode), f(r.group_start), f(r.group_length);
  }
};

struct DataEnd {
  static constexpr Op op = Op::data_end;
  std::uint32_t data_section_crc = 0;
  template <class F, class R>
  static void fields(F& f, R& r) {
    f(r.data_section_crc);
  }
};

/// A record's opcode and content, as found in a file.
struct RawRecord {
  Op op{};
  std::string_view content;
  std::uint64_t offset = 0;  // of the opcode, from the start of the file or chunk
};

/// Appends the whole record (opcode, length, content) to `out`.
template <class R>
void append_record(std::string& out, const R& record);

/// The record's fields read from its content; unknown trailing fields are ignored (the spec lets
/// records grow). Throws InputError "<where>: <record> record: ..." when a field is cut short
/// or an attachment's CRC is wrong.
template <class R>
R parse_record(std::string_view content, const std::string& where);

/// The next record of `bytes` at `offset`, or nothing when fewer than its nine header bytes or
/// its content remain (a file cut short). Advances `offset` past it.
bool next_record(std::string_view bytes, std::uint64_t& offset, RawRecord& record);

/// The record type's name for messages ("chunk", "message index", ...).
std::string op_name(Op op);

}  // namespace ballsight::mcap
