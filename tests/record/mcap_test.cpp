// MCAP files written and read back: every record type, each compression, the indexes pointing at
// their records, a file cut short (and one whose writer was killed), damaged bytes refused.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

#include "ballsight/core/error.hpp"
#include "ballsight/record/mcap_reader.hpp"
#include "ballsight/record/mcap_writer.hpp"
#include "file_size_limit.hpp"
#include "temp_dir.hpp"

namespace ballsight::mcap {
namespace {

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A writer's options: `compression`, chunks of `chunk_size` bytes.
WriterOptions writer_options(Compression compression, std::size_t chunk_size) {
  WriterOptions options;
  options.compression = compression;
  options.chunk_size = chunk_size;
  options.library = "ballsight test";
  return options;
}

/// Message i of a test recording: on channel 1 + i % 3, 1 ms apart, of varied length.
Message test_message(std::uint32_t i) {
  const std::uint64_t t = 1'700'000'000'000'000'000ULL + std::uint64_t{i} * 1'000'000ULL;
  return Message{
      static_cast<std::uint16_t>(1 + i % 3),
      i,
      t,
      t + 5,
      {"{\"i\":" + std::to_string(i) + ",\"pad\":\"" + std::string(i % 50, 'x') + "\"}"}};
}

constexpr std::uint32_t kMessages = 600;

/// A recording of kMessages messages on three channels (two schemas), an attachment and a
/// metadata record, in chunks of about 4 kB.
void write_test_file(const std::filesystem::path& path, Compression compression) {
  McapWriter writer(path, writer_options(compression, 4096));
  const std::uint16_t pose =
      writer.add_schema("ballsight.Pose", "jsonschema", "{\"type\":\"object\"}");
  const std::uint16_t image = writer.add_schema("foxglove.CompressedImage", "jsonschema", "{}");
  writer.add_channel(pose, "/robot/pose", "json", {{"frame", "court"}});
  writer.add_channel(image, "/camera/1/image", "json");
  writer.add_channel(0, "/log", "json");
  writer.attach({1, 2, "site.yml", "application/yaml", {"court: {}\n"}});
  for (std::uint32_t i = 0; i < kMessages; ++i) writer.write(test_message(i));
  writer.write_metadata({"ballsight", {{"version", "test"}, {"cameras", "4"}}});
  writer.close();
}

/// A test recording on disk, with its bytes and its summary.
struct TestFile {
  explicit TestFile(Compression compression) {
    write_test_file(path, compression);
    bytes = file_bytes(path);
    summary = *McapReader::open(path).summary();
  }
  test::TempDir dir;
  std::filesystem::path path = dir / "run.mcap";
  std::string bytes;
  Summary summary;
};

class McapRoundTrip : public ::testing::TestWithParam<Compression> {};

TEST_P(McapRoundTrip, EveryRecordReadsBackAsWritten) {
  test::TempDir dir;
  const auto path = dir / "run.mcap";
  write_test_file(path, GetParam());
  const McapReader reader = McapReader::open(path);
  EXPECT_EQ(reader.header().library, "ballsight test");
  EXPECT_TRUE(reader.closed());
  std::vector<Message> messages;
  std::vector<std::string> topics;
  const DataSection data = reader.read([&](const Channel& channel, const Message& message) {
    messages.push_back(message);
    topics.push_back(channel.topic);
  });
  EXPECT_TRUE(data.complete) << data.cut;
  ASSERT_EQ(messages.size(), kMessages);
  for (std::uint32_t i = 0; i < kMessages; ++i) EXPECT_EQ(messages[i], test_message(i)) << i;
  EXPECT_EQ(topics[0], "/robot/pose");
  EXPECT_EQ(topics[1], "/camera/1/image");
  EXPECT_GT(data.chunk_count, 3u);
  EXPECT_EQ(data.channels.at(1).metadata.at("frame"), "court");
  EXPECT_EQ(data.schemas.at(2).name, "foxglove.CompressedImage");
  ASSERT_EQ(data.attachments.size(), 1u);
  EXPECT_EQ(data.attachments[0].data.bytes, "court: {}\n");
  ASSERT_EQ(data.metadata.size(), 1u);
  EXPECT_EQ(data.metadata[0].metadata.at("cameras"), "4");

  ASSERT_TRUE(reader.summary());
  const Summary& summary = *reader.summary();
  ASSERT_TRUE(summary.statistics);
  EXPECT_EQ(summary.statistics->message_count, kMessages);
  EXPECT_EQ(summary.statistics->chunk_count, data.chunk_count);
  EXPECT_EQ(summary.statistics->channel_message_counts.at(3), kMessages / 3);
  EXPECT_EQ(summary.statistics->message_start_time, test_message(0).log_time);
  EXPECT_EQ(summary.statistics->message_end_time, test_message(kMessages - 1).log_time);
  EXPECT_EQ(summary.chunk_indexes.size(), data.chunk_count);
  EXPECT_EQ(summary.schemas.size(), 2u);
  EXPECT_EQ(summary.channels.size(), 3u);
  EXPECT_EQ(summary.attachment_indexes.size(), 1u);
  EXPECT_EQ(summary.metadata_indexes.size(), 1u);
  for (const ChunkIndex& index : summary.chunk_indexes) {
    EXPECT_EQ(index.compression, compression_name(GetParam()));
  }
}

INSTANTIATE_TEST_SUITE_P(Compressions, McapRoundTrip,
                         ::testing::Values(Compression::none, Compression::zstd, Compression::lz4),
                         [](const auto& param) {
                           return param.param == Compression::none ? std::string("none")
                                                                   : compression_name(param.param);
                         });

/// The record at `offset` of `bytes`, which must be of type `op`.
RawRecord record_at(std::string_view bytes, std::uint64_t offset, Op op) {
  RawRecord record;
  const std::uint64_t start = offset;
  EXPECT_TRUE(next_record(bytes, offset, record)) << "at " << start;
  EXPECT_EQ(op_name(record.op), op_name(op)) << "at " << start;
  return record;
}

TEST(McapIndexes, ChunkMessageAttachmentAndSummaryOffsetsPointAtTheirRecords) {
  const TestFile file(Compression::zstd);
  const std::string& bytes = file.bytes;
  const Summary& summary = file.summary;
  std::uint64_t indexed = 0;
  for (const ChunkIndex& index : summary.chunk_indexes) {
    const RawRecord record = record_at(bytes, index.chunk_start_offset, Op::chunk);
    EXPECT_EQ(record.content.size() + 9, index.chunk_length);
    const Chunk chunk = parse_record<Chunk>(record.content, "chunk");
    EXPECT_EQ(chunk.records.bytes.size(), index.compressed_size);
    const std::string records =
        decompress(chunk.compression, chunk.records.bytes, chunk.uncompressed_size, "chunk");
    std::uint64_t index_bytes = 0;
    for (const auto& [channel, offset] : index.message_index_offsets) {
      const RawRecord index_record = record_at(bytes, offset, Op::message_index);
      index_bytes += index_record.content.size() + 9;
      const MessageIndex message_index = parse_record<MessageIndex>(index_record.content, "index");
      EXPECT_EQ(message_index.channel_id, channel);
      for (const auto& [log_time, message_offset] : message_index.records) {
        const Message message = parse_record<Message>(
            record_at(records, message_offset, Op::message).content, "message");
        EXPECT_EQ(message.channel_id, channel);
        EXPECT_EQ(message.log_time, log_time);
        EXPECT_GE(log_time, index.message_start_time);
        EXPECT_LE(log_time, index.message_end_time);
        ++indexed;
      }
    }
    EXPECT_EQ(index_bytes, index.message_index_length);
  }
  EXPECT_EQ(indexed, kMessages);
  const AttachmentIndex& attachment = summary.attachment_indexes.at(0);
  const RawRecord record = record_at(bytes, attachment.offset, Op::attachment);
  EXPECT_EQ(record.content.size() + 9, attachment.length);
  EXPECT_EQ(parse_record<Attachment>(record.content, "attachment").name, "site.yml");
  const MetadataIndex& metadata = summary.metadata_indexes.at(0);
  EXPECT_EQ(
      parse_record<Metadata>(record_at(bytes, metadata.offset, Op::metadata).content, "m").name,
      "ballsight");

  // The summary offsets: one per group, each covering records of its opcode only.
  const std::uint64_t footer_at = bytes.size() - 8 - 29;
  const Footer footer = parse_record<Footer>(record_at(bytes, footer_at, Op::footer).content, "f");
  std::uint64_t offset = footer.summary_offset_start;
  int groups = 0;
  while (offset < footer_at) {
    const SummaryOffset group = parse_record<SummaryOffset>(
        record_at(bytes, offset, Op::summary_offset).content, "summary offset");
    offset += 9 + 17;
    for (std::uint64_t at = group.group_start; at < group.group_start + group.group_length;) {
      RawRecord member;
      ASSERT_TRUE(next_record(bytes, at, member));
      EXPECT_EQ(static_cast<int>(member.op), group.group_opcode);
    }
    ++groups;
  }
  EXPECT_EQ(groups, 6);  // schemas, channels, statistics, chunk, attachment, metadata indexes
}

/// What a reader finds in `bytes`, which must be a file cut short: its messages, and the byte
/// after the last record it read.
struct CutRead {
  std::vector<Message> messages;
  std::uint64_t read_to = 0;
};
CutRead read_cut(const std::string& bytes) {
  const McapReader reader(bytes, "cut.mcap");
  EXPECT_FALSE(reader.closed());
  EXPECT_FALSE(reader.summary());
  CutRead found;
  const DataSection data = reader.read(
      [&](const Channel&, const Message& message) { found.messages.push_back(message); });
  EXPECT_FALSE(data.complete);
  EXPECT_NE(data.cut.find("cut short"), std::string::npos) << data.cut;
  found.read_to = data.read_to;
  return found;
}

/// The messages of the chunk `index` points at.
std::size_t messages_in(const std::string& bytes, const ChunkIndex& index) {
  std::size_t count = 0;
  for (const auto& [channel, offset] : index.message_index_offsets) {
    std::uint64_t at = offset;
    RawRecord record;
    EXPECT_TRUE(next_record(bytes, at, record));
    count += parse_record<MessageIndex>(record.content, "index").records.size();
  }
  return count;
}

TEST(McapCut, AFileCutAnywhereReadsExactlyItsCompleteChunks) {
  const TestFile file(Compression::lz4);
  std::size_t before = 0;  // messages in the chunks before the cut one
  for (const ChunkIndex& index : file.summary.chunk_indexes) {
    const std::string cut = file.bytes.substr(0, index.chunk_start_offset + index.chunk_length / 2);
    const CutRead read = read_cut(cut);
    ASSERT_EQ(read.messages.size(), before);
    for (std::size_t i = 0; i < read.messages.size(); ++i) {
      ASSERT_EQ(read.messages[i], test_message(static_cast<std::uint32_t>(i)));
    }
    EXPECT_EQ(read.read_to, index.chunk_start_offset);  // up to the cut chunk, indexes included
    before += messages_in(file.bytes, index);
  }
  EXPECT_EQ(before, kMessages);
}

TEST(McapCut, AWriterKilledMidRecordingLeavesItsCompleteChunks) {
  test::TempDir dir;
  const auto path = dir / "killed.mcap";
  constexpr std::size_t kChunk = 2048;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // writes until killed (or, should the test hang, for a few minutes)
    try {
      McapWriter writer(path, writer_options(Compression::zstd, kChunk));
      writer.add_channel(0, "/log", "json");
      writer.add_channel(0, "/log2", "json");
      writer.add_channel(0, "/log3", "json");
      for (std::uint32_t i = 0; i < 100'000'000; ++i) writer.write(test_message(i % kMessages));
    } catch (...) {
      _exit(1);
    }
    _exit(0);
  }
  // Wait (at most 20 s) for a few chunks on disk, then kill the writer.
  std::error_code no_file;
  for (int waited = 0;
       waited < 2000 && (std::filesystem::file_size(path, no_file) < 50'000 || no_file); ++waited) {
    usleep(10'000);
  }
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  const std::string bytes = file_bytes(path);
  const CutRead read = read_cut(bytes);
  ASSERT_GT(read.messages.size(), 100u);
  for (std::size_t i = 0; i < read.messages.size(); ++i) {
    ASSERT_EQ(read.messages[i], test_message(static_cast<std::uint32_t>(i % kMessages))) << i;
  }
  // What is lost is the chunk being written when the writer was killed, at most.
  EXPECT_LT(bytes.size() - read.read_to, kChunk + 4096);
}

TEST(McapCut, AWriteRefusedByTheDiskLeavesAFileCutShort) {
  test::TempDir dir;
  const auto path = dir / "full.mcap";
  std::string error;
  {
    const test::FileSizeLimit full_disk(40'000);
    McapWriter writer(path, writer_options(Compression::none, 4096));
    writer.add_channel(0, "/log", "json");
    writer.add_channel(0, "/log2", "json");
    writer.add_channel(0, "/log3", "json");
    try {
      for (std::uint32_t i = 0; i < 10'000; ++i) writer.write(test_message(i % kMessages));
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
    EXPECT_THROW(writer.write(test_message(0)), std::logic_error);
    writer.close();  // only closes: nothing more is written after the failure
  }
  EXPECT_NE(error.find(path.string() + ": cannot write"), std::string::npos) << error;
  const std::string bytes = file_bytes(path);
  EXPECT_LE(bytes.size(), 40'000u);
  const CutRead read = read_cut(bytes);
  EXPECT_GT(read.messages.size(), 50u);
  for (std::size_t i = 0; i < read.messages.size(); ++i) {
    ASSERT_EQ(read.messages[i], test_message(static_cast<std::uint32_t>(i))) << i;
  }
}

/// `bytes` with the byte at `offset` changed.
std::string flipped(std::string bytes, std::uint64_t offset) {
  bytes[offset] = static_cast<char>(bytes[offset] ^ 0x5A);
  return bytes;
}

void expect_refused(const std::string& bytes, const std::string& part) {
  try {
    McapReader(bytes, "bad.mcap").read();
    ADD_FAILURE() << "accepted; expected an error with \"" << part << "\"";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("bad.mcap: "), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(McapDamage, WrongBytesAreRefusedWithWhereAndWhat) {
  const TestFile file(Compression::none);
  const std::string& bytes = file.bytes;
  const Summary& summary = file.summary;
  const ChunkIndex& chunk = summary.chunk_indexes.at(1);
  // A message's byte inside an uncompressed chunk: the chunk's CRC.
  expect_refused(flipped(bytes, chunk.chunk_start_offset + chunk.chunk_length - 3),
                 "the chunk's CRC does not match");
  expect_refused(flipped(bytes, bytes.size() - 40), "the summary's CRC does not match");
  expect_refused(flipped(bytes, 1), "not an MCAP file");
  expect_refused("", "not an MCAP file");
  // A data section byte outside any chunk (the attachment's name): the attachment's CRC.
  const AttachmentIndex& attachment = summary.attachment_indexes.at(0);
  expect_refused(flipped(bytes, attachment.offset + 9 + 16 + 4), "the CRC does not match");

  // A closed file whose chunk claims to run past the file's end.
  std::string long_chunk = bytes;
  long_chunk[chunk.chunk_start_offset + 6] = static_cast<char>(0x7f);
  expect_refused(long_chunk, "a record runs past the end of the file");

  // A message on a channel that was never defined.
  std::string handmade(kMagic);
  append_record(handmade, Header{"", "hand"});
  append_record(handmade, test_message(1));
  expect_refused(handmade, "a message on channel 2, not defined before it");
  // A chunk that claims more than the reader's limit.
  std::string huge(kMagic);
  append_record(huge, Header{});
  append_record(huge, Chunk{0, 0, std::uint64_t{1} << 40, 0, "zstd", {"x"}});
  expect_refused(huge, "at most");
  // A chunk whose compression nobody knows.
  std::string unknown(kMagic);
  append_record(unknown, Header{});
  append_record(unknown, Chunk{0, 0, 1, 0, "brotli", {"x"}});
  expect_refused(unknown, "unknown compression \"brotli\"");
}

TEST(McapWriterErrors, AnUnwritablePathIsAnInputErrorNamingIt) {
  try {
    McapWriter writer("/nonexistent-dir/run.mcap");
    FAIL() << "opened";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent-dir/run.mcap: cannot open for writing"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(parse_compression("gzip", "--record-compression"), InputError);
}

}  // namespace
}  // namespace ballsight::mcap
