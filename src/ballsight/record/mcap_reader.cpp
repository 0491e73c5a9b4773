#include "ballsight/record/mcap_reader.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "ballsight/core/checksum.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/record/compression.hpp"

namespace ballsight::mcap {
namespace {

constexpr std::uint64_t kRecordPrefix = 9;  // opcode and content length
constexpr std::uint64_t kFooterRecord = kRecordPrefix + 20;

std::string at(const std::string& where, std::uint64_t offset) {
  return where + ": byte " + std::to_string(offset);
}

std::string_view whole(const RawRecord& record, std::string_view bytes) {
  return bytes.substr(record.offset, kRecordPrefix + record.content.size());
}

/// Keeps a schema or channel by id; the same id twice must be the same record.
template <class R>
void keep(std::map<std::uint16_t, R>& kept, const R& record, const std::string& where) {
  const auto [it, added] = kept.emplace(record.id, record);
  require(added || it->second == record, where,
          "a second, different " + op_name(R::op) + " with id " + std::to_string(record.id));
}

}  // namespace

McapReader McapReader::open(const std::filesystem::path& path, ReaderLimits limits) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(path.string() + ": cannot open (" + std::strerror(errno) + ")");
  struct stat status {};
  const bool stated = ::fstat(fd, &status) == 0 && S_ISREG(status.st_mode);
  const auto size = static_cast<std::size_t>(status.st_size);
  void* data = stated && size > 0 ? ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0) : nullptr;
  const int map_error = errno;
  ::close(fd);
  if (!stated) throw InputError(path.string() + ": not a regular file");
  if (data == MAP_FAILED) {
    throw InputError(path.string() + ": cannot map (" + std::strerror(map_error) + ")");
  }
  std::shared_ptr<const void> mapping(data, [size](const void* p) {
    if (p != nullptr) ::munmap(const_cast<void*>(p), size);
  });
  McapReader reader(std::string_view(static_cast<const char*>(data), size), path.string(), limits);
  reader.mapping_ = std::move(mapping);
  return reader;
}

McapReader::McapReader(std::string_view bytes, std::string where, ReaderLimits limits)
    : bytes_(bytes), where_(std::move(where)), limits_(limits) {
  require(bytes_.substr(0, kMagic.size()) == kMagic, where_,
          "not an MCAP file (it does not begin with the MCAP magic bytes)");
  std::uint64_t offset = kMagic.size();
  RawRecord record;
  require(next_record(bytes_, offset, record) && record.op == Op::header, at(where_, 8),
          "the file does not go on with a header record");
  header_ = parse_record<Header>(record.content, at(where_, 8));
  read_footer();
}

void McapReader::read_footer() {
  const std::uint64_t size = bytes_.size();
  if (size < 2 * kMagic.size() + kFooterRecord || bytes_.substr(size - kMagic.size()) != kMagic) {
    return;  // cut short: no footer
  }
  const std::uint64_t footer_at = size - kMagic.size() - kFooterRecord;
  std::uint64_t offset = footer_at;
  RawRecord record;
  if (!next_record(bytes_, offset, record) || record.op != Op::footer) return;
  const Footer footer = parse_record<Footer>(record.content, at(where_, footer_at));
  closed_ = true;
  if (footer.summary_start == 0) return;
  const std::string where = at(where_, footer_at) + " (footer)";
  require(footer.summary_start <= footer_at, where, "the summary starts after the footer");
  require(
      footer.summary_offset_start == 0 || (footer.summary_offset_start >= footer.summary_start &&
                                           footer.summary_offset_start <= footer_at),
      where, "the summary offsets lie outside the summary");
  if (footer.summary_crc != 0) {
    const std::string_view covered =
        bytes_.substr(footer.summary_start, footer_at + kRecordPrefix + 16 - footer.summary_start);
    require(crc32(0, covered) == footer.summary_crc, where, "the summary's CRC does not match");
  }
  const std::string_view summary = bytes_.substr(0, footer_at);
  Summary found;
  offset = footer.summary_start;
  while (offset < footer_at) {
    const std::string record_at = at(where_, offset);
    require(next_record(summary, offset, record), record_at, "a summary record is cut short");
    switch (record.op) {
      case Op::schema:
        found.schemas.push_back(parse_record<Schema>(record.content, record_at));
        break;
      case Op::channel:
        found.channels.push_back(parse_record<Channel>(record.content, record_at));
        break;
      case Op::statistics:
        found.statistics = parse_record<Statistics>(record.content, record_at);
        break;
      case Op::chunk_index:
        found.chunk_indexes.push_back(parse_record<ChunkIndex>(record.content, record_at));
        break;
      case Op::attachment_index:
        found.attachment_indexes.push_back(
            parse_record<AttachmentIndex>(record.content, record_at));
        break;
      case Op::metadata_index:
        found.metadata_indexes.push_back(parse_record<MetadataIndex>(record.content, record_at));
        break;
      default:
        break;  // summary offsets, private records
    }
  }
  summary_ = std::move(found);
}

DataSection McapReader::read(const MessageCallback& on_message) const {
  DataSection found;
  std::uint64_t offset = kMagic.size();
  RawRecord record;
  next_record(bytes_, offset, record);  // the header, checked when opened
  std::uint32_t crc = crc32(0, bytes_.substr(0, offset));
  while (true) {
    const std::uint64_t record_at = offset;
    if (!next_record(bytes_, offset, record)) {
      // A closed file has all its records: one that runs past the end is damage.
      require(!closed_, at(where_, record_at), "a record runs past the end of the file");
      found.cut = "the data section is cut short at byte " + std::to_string(record_at) +
                  " (a writer that was stopped before closing the file)";
      break;
    }
    const std::string where = at(where_, record_at);
    found.read_to = offset;
    if (record.op == Op::data_end) {
      const DataEnd end = parse_record<DataEnd>(record.content, where);
      require(end.data_section_crc == 0 || end.data_section_crc == crc, where,
              "the data section's CRC does not match");
      found.complete = true;
      break;
    }
    crc = crc32(crc, whole(record, bytes_));
    switch (record.op) {
      case Op::schema:
      case Op::channel:
      case Op::message:
        read_records(whole(record, bytes_), where_ + ": byte ", record_at, found, on_message);
        break;
      case Op::chunk:
        read_chunk(record, found, on_message);
        break;
      case Op::attachment:
        found.attachments.push_back(parse_record<Attachment>(record.content, where));
        break;
      case Op::metadata:
        found.metadata.push_back(parse_record<Metadata>(record.content, where));
        break;
      case Op::header:
      case Op::footer:
        throw InputError(where + ": a " + op_name(record.op) + " record inside the data section");
      default:
        break;  // indexes, private records
    }
  }
  return found;
}

void McapReader::read_chunk(const RawRecord& record, DataSection& found,
                            const MessageCallback& on_message) const {
  const std::string where = at(where_, record.offset);
  const Chunk chunk = parse_record<Chunk>(record.content, where);
  require(chunk.uncompressed_size <= limits_.max_chunk_bytes, where,
          "a chunk of " + std::to_string(chunk.uncompressed_size) + " bytes (at most " +
              std::to_string(limits_.max_chunk_bytes) + " are read)");
  const std::string records = decompress(chunk.compression, chunk.records.bytes,
                                         chunk.uncompressed_size, where + " (chunk)");
  require(chunk.uncompressed_crc == 0 || chunk.uncompressed_crc == crc32(0, records), where,
          "the chunk's CRC does not match");
  ++found.chunk_count;
  found.compressions.insert(chunk.compression.empty() ? "none" : chunk.compression);
  read_records(records, where + ", chunk byte ", 0, found, on_message);
}

/// Schema, channel and message records, a chunk's or one standing in the data section; `where`
/// followed by `base` plus a record's offset in `records` names it.
void McapReader::read_records(std::string_view records, const std::string& where,
                              std::uint64_t base, DataSection& found,
                              const MessageCallback& on_message) const {
  std::uint64_t offset = 0;
  RawRecord inner;
  while (offset < records.size()) {
    const std::string inner_where = where + std::to_string(base + offset);
    require(next_record(records, offset, inner), inner_where, "a record is cut short");
    if (inner.op == Op::schema) {
      const Schema schema = parse_record<Schema>(inner.content, inner_where);
      if (schema.id != 0) keep(found.schemas, schema, inner_where);
    } else if (inner.op == Op::channel) {
      const Channel channel = parse_record<Channel>(inner.content, inner_where);
      require(channel.schema_id == 0 || found.schemas.contains(channel.schema_id), inner_where,
              "channel " + std::to_string(channel.id) + " names schema " +
                  std::to_string(channel.schema_id) + ", not defined before it");
      keep(found.channels, channel, inner_where);
    } else if (inner.op == Op::message) {
      const Message message = parse_record<Message>(inner.content, inner_where);
      const auto channel = found.channels.find(message.channel_id);
      require(
          channel != found.channels.end(), inner_where,
          "a message on channel " + std::to_string(message.channel_id) + ", not defined before it");
      ++found.message_count;
      if (on_message) on_message(channel->second, message);
    }
  }
}

}  // namespace ballsight::mcap
