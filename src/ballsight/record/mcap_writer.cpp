#include "ballsight/record/mcap_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "ballsight/core/checksum.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight::mcap {
namespace {

std::unique_ptr<std::FILE, int (*)(std::FILE*)> open_for_writing(
    const std::filesystem::path& path) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) {
    throw InputError(path.string() + ": cannot open for writing (" + std::strerror(errno) + ")");
  }
  return {file, &std::fclose};
}

template <class R>
std::string record_bytes(const R& record) {
  std::string bytes;
  append_record(bytes, record);
  return bytes;
}

}  // namespace

McapWriter::McapWriter(const std::filesystem::path& path, WriterOptions options)
    : path_(path), options_(std::move(options)), file_(open_for_writing(path)) {
  put(std::string(kMagic));
  put_record(Header{options_.profile, options_.library});
  if (std::fflush(file_.get()) != 0) {
    throw InputError(path_.string() + ": cannot write (" + std::strerror(errno) + ")");
  }
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (const std::exception&) {
  }
}

void McapWriter::check_open() const {
  if (closed_ || failed_) {
    throw std::logic_error("McapWriter: " + path_.string() + (failed_ ? " failed" : " is closed"));
  }
}

void McapWriter::fail(const char* what) {
  failed_ = true;
  throw std::runtime_error(path_.string() + ": cannot " + what + " (" + std::strerror(errno) + ")");
}

void McapWriter::put(const std::string& bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_.get()) != bytes.size()) fail("write");
  offset_ += bytes.size();
  data_crc_ = crc32(data_crc_, bytes);
}

template <class R>
void McapWriter::put_record(const R& record) {
  put(record_bytes(record));
}

std::uint16_t McapWriter::add_schema(const std::string& name, const std::string& encoding,
                                     const std::string& data) {
  check_open();
  schemas_.push_back(Schema{static_cast<std::uint16_t>(schemas_.size() + 1), name, encoding, data});
  put_record(schemas_.back());
  return schemas_.back().id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id, const std::string& topic,
                                      const std::string& message_encoding,
                                      const StringMap& metadata) {
  check_open();
  if (schema_id > schemas_.size()) {
    throw std::invalid_argument("McapWriter: no schema " + std::to_string(schema_id));
  }
  channels_.push_back(Channel{static_cast<std::uint16_t>(channels_.size() + 1), schema_id, topic,
                              message_encoding, metadata});
  put_record(channels_.back());
  return channels_.back().id;
}

void McapWriter::write(const Message& message) {
  check_open();
  if (message.channel_id == 0 || message.channel_id > channels_.size()) {
    throw std::invalid_argument("McapWriter: no channel " + std::to_string(message.channel_id));
  }
  if (chunk_records_.empty()) chunk_start_time_ = chunk_end_time_ = message.log_time;
  chunk_start_time_ = std::min(chunk_start_time_, message.log_time);
  chunk_end_time_ = std::max(chunk_end_time_, message.log_time);
  chunk_index_entries_[message.channel_id].emplace_back(message.log_time, chunk_records_.size());
  append_record(chunk_records_, message);

  statistics_.count(message);
  if (chunk_records_.size() >= options_.chunk_size ||
      chunk_end_time_ - chunk_start_time_ >= options_.chunk_duration_ns) {
    flush_chunk();
  }
}

void McapWriter::flush_chunk() {
  if (chunk_records_.empty()) return;
  Chunk chunk{chunk_start_time_,
              chunk_end_time_,
              chunk_records_.size(),
              crc32(0, chunk_records_),
              compression_name(options_.compression),
              {compress(options_.compression, chunk_records_)}};
  ChunkIndex index{
      chunk_start_time_,          chunk_end_time_,        offset_, 0, {}, 0, chunk.compression,
      chunk.records.bytes.size(), chunk.uncompressed_size};
  put_record(chunk);
  index.chunk_length = offset_ - index.chunk_start_offset;
  const std::uint64_t indexes_start = offset_;
  for (auto& [channel, entries] : chunk_index_entries_) {
    index.message_index_offsets[channel] = offset_;
    put_record(MessageIndex{channel, std::move(entries)});
  }
  index.message_index_length = offset_ - indexes_start;
  chunk_indexes_.push_back(std::move(index));
  ++statistics_.chunk_count;
  chunk_records_.clear();
  chunk_index_entries_.clear();
  if (std::fflush(file_.get()) != 0) fail("write");
}

void McapWriter::attach(const Attachment& attachment) {
  check_open();
  flush_chunk();  // attachments stand outside chunks
  AttachmentIndex index{offset_,
                        0,
                        attachment.log_time,
                        attachment.create_time,
                        attachment.data.bytes.size(),
                        attachment.name,
                        attachment.media_type};
  put_record(attachment);
  index.length = offset_ - index.offset;
  attachment_indexes_.push_back(std::move(index));
  ++statistics_.attachment_count;
}

void McapWriter::write_metadata(const Metadata& metadata) {
  check_open();
  flush_chunk();
  MetadataIndex index{offset_, 0, metadata.name};
  put_record(metadata);
  index.length = offset_ - index.offset;
  metadata_indexes_.push_back(std::move(index));
  ++statistics_.metadata_count;
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  if (failed_) {  // what is on disk stays a file cut short, which readers read up to its end
    file_.reset();
    return;
  }
  flush_chunk();
  put_record(DataEnd{data_crc_});

  // The summary, grouped by opcode, and one summary offset per group.
  const std::uint64_t summary_start = offset_;
  std::string summary;
  std::vector<SummaryOffset> offsets;
  const auto group = [&](Op op, const auto& records) {
    if (records.empty()) return;
    const std::uint64_t start = summary_start + summary.size();
    for (const auto& record : records) append_record(summary, record);
    offsets.push_back(SummaryOffset{static_cast<std::uint8_t>(op), start,
                                    summary_start + summary.size() - start});
  };
  statistics_.schema_count = static_cast<std::uint16_t>(schemas_.size());
  statistics_.channel_count = static_cast<std::uint32_t>(channels_.size());
  group(Op::schema, schemas_);
  group(Op::channel, channels_);
  group(Op::statistics, std::vector<Statistics>{statistics_});
  group(Op::chunk_index, chunk_indexes_);
  group(Op::attachment_index, attachment_indexes_);
  group(Op::metadata_index, metadata_indexes_);
  const std::uint64_t summary_offset_start = summary_start + summary.size();
  for (const SummaryOffset& offset : offsets) append_record(summary, offset);

  // The footer's CRC covers the summary and the footer's fields before it.
  std::string footer = record_bytes(Footer{summary_start, summary_offset_start, 0});
  footer.resize(footer.size() - 4);
  const std::uint32_t summary_crc = crc32(crc32(0, summary), footer);
  put(summary);
  put_record(Footer{summary_start, summary_offset_start, summary_crc});
  put(std::string(kMagic));
  if (std::fclose(file_.release()) != 0) fail("write");
}

}  // namespace ballsight::mcap
