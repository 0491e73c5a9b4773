#pragma once
// Writes an MCAP file: messages in compressed chunks (of about 1 MB or 1 s), each followed by its
// message indexes; then the summary (schemas, channels, statistics, chunk, attachment and metadata
// indexes, grouped by opcode), the summary offsets and the footer, with the data section's and the
// summary's CRCs, so that readers can seek by time and topic. Schemas and channels are written to
// the data section as they are added and the file is flushed after every chunk: a writer that is
// killed leaves a file whose every complete chunk a reader still reads (McapReader).

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/record/compression.hpp"
#include "ballsight/record/mcap_format.hpp"

namespace ballsight::mcap {

struct WriterOptions {
  Compression compression = Compression::zstd;
  /// A chunk is closed, compressed and written once its records reach this size or its messages
  /// span this long (what a killed writer can lose).
  std::size_t chunk_size = 1 << 20;
  std::uint64_t chunk_duration_ns = 1'000'000'000;
  std::string profile;  // the Header's profile: "" (none of the well-known ones)
  std::string library = "ballsight";
};

class McapWriter {
 public:
  /// Creates (or replaces) `path` and writes the magic and the header; throws InputError naming
  /// the path when it cannot be opened for writing.
  McapWriter(const std::filesystem::path& path, WriterOptions options = {});
  /// Closes the file as close() does; an error there is swallowed (call close() to see it).
  ~McapWriter();
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  /// A schema (encoding "jsonschema" for JSON messages); its id (from 1).
  std::uint16_t add_schema(const std::string& name, const std::string& encoding,
                           const std::string& data);
  /// A channel on `topic` with messages of `schema_id` (0: none); its id.
  std::uint16_t add_channel(std::uint16_t schema_id, const std::string& topic,
                            const std::string& message_encoding, const StringMap& metadata = {});
  /// A message on an added channel; log times should not go back (readers sort by chunk).
  void write(const Message& message);
  void attach(const Attachment& attachment);
  void write_metadata(const Metadata& metadata);
  /// Writes the open chunk, the data end, the summary and the footer, and closes the file.
  /// Throws std::runtime_error naming the path when the disk refuses a byte (full, removed).
  /// After any failed write the writer only closes the file: what reached the disk reads as a
  /// file cut short, and every other call throws std::logic_error.
  void close();

  /// Bytes in the file so far plus the open chunk's uncompressed records.
  std::uint64_t size() const { return offset_ + chunk_records_.size(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  void check_open() const;
  [[noreturn]] void fail(const char* what);  // marks the writer failed and throws
  void put(const std::string& bytes);        // appends to the file and the data section's CRC
  void flush_chunk();
  template <class R>
  void put_record(const R& record);

  std::filesystem::path path_;
  WriterOptions options_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
  std::uint64_t offset_ = 0;
  std::uint32_t data_crc_ = 0;
  bool closed_ = false;
  bool failed_ = false;

  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::string chunk_records_;
  std::map<std::uint16_t, TimeOffsets> chunk_index_entries_;
  std::uint64_t chunk_start_time_ = 0;
  std::uint64_t chunk_end_time_ = 0;
  std::vector<ChunkIndex> chunk_indexes_;
  std::vector<AttachmentIndex> attachment_indexes_;
  std::vector<MetadataIndex> metadata_indexes_;
  Statistics statistics_;
};

}  // namespace ballsight::mcap
