#pragma once
// Reads an MCAP file (https://mcap.dev/spec): its summary through the footer when the file was
// closed, and its data section record by record (chunks decompressed and their CRCs checked).
// A file whose writer was killed has no footer: it is read up to its last complete record, and
// what was cut is reported rather than refused. Anything else that breaks the specification (a
// wrong magic, a record cut inside a chunk, a CRC that does not match, a message on a channel
// never defined) is an InputError naming the file and the byte offset.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/record/mcap_format.hpp"

namespace ballsight::mcap {

struct ReaderLimits {
  /// A chunk whose records would decompress to more is refused (a damaged or hostile length).
  std::uint64_t max_chunk_bytes = std::uint64_t{1} << 30;
};

/// The summary section of a closed file.
struct Summary {
  std::vector<Schema> schemas;
  std::vector<Channel> channels;
  std::optional<Statistics> statistics;
  std::vector<ChunkIndex> chunk_indexes;
  std::vector<AttachmentIndex> attachment_indexes;
  std::vector<MetadataIndex> metadata_indexes;
};

/// What a pass over the data section found.
struct DataSection {
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;
  std::vector<Attachment> attachments;
  std::vector<Metadata> metadata;
  std::uint64_t message_count = 0;
  std::uint64_t chunk_count = 0;
  std::set<std::string> compressions;  // of the chunks read ("none" for uncompressed ones)
  bool complete = false;               // the data end record was reached
  std::uint64_t read_to = 0;           // the byte after the last record read
  std::string cut;                     // why reading stopped early ("" when complete)
};

class McapReader {
 public:
  /// Maps the file; throws InputError naming it when it cannot be read or is not MCAP.
  static McapReader open(const std::filesystem::path& path, ReaderLimits limits = {});
  /// Reads `bytes` (kept alive by the caller), named `where` in errors.
  McapReader(std::string_view bytes, std::string where, ReaderLimits limits = {});

  const Header& header() const { return header_; }
  /// The summary, or nothing when the file has no footer (cut short) or no summary section.
  const std::optional<Summary>& summary() const { return summary_; }
  /// True when the file ends with a footer and the closing magic.
  bool closed() const { return closed_; }

  using MessageCallback = std::function<void(const Channel&, const Message&)>;
  /// Every message in file order, with its channel; returns what the pass found.
  DataSection read(const MessageCallback& on_message = {}) const;

  const std::string& where() const { return where_; }

 private:
  void read_footer();
  void read_chunk(const RawRecord& record, DataSection& found,
                  const MessageCallback& on_message) const;
  void read_records(std::string_view records, const std::string& where, std::uint64_t base,
                    DataSection& found, const MessageCallback& on_message) const;

  std::shared_ptr<const void> mapping_;  // the mapped file, when opened from a path
  std::string_view bytes_;
  std::string where_;
  ReaderLimits limits_;
  Header header_;
  std::optional<Summary> summary_;
  bool closed_ = false;
};

}  // namespace ballsight::mcap
