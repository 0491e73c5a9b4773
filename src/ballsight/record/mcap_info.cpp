#include "ballsight/record/mcap_info.hpp"

namespace ballsight::mcap {
namespace {

/// What the summary says that the data section does not ("agrees" when nothing).
std::string check_summary(const Summary& summary, const DataSection& data,
                          const Statistics& counted) {
  if (!summary.statistics) return "no statistics record";
  const Statistics& s = *summary.statistics;
  if (s.message_count != counted.message_count) return "message count";
  if (s.chunk_count != data.chunk_count) return "chunk count";
  if (s.channel_message_counts != counted.channel_message_counts) return "per-channel counts";
  if (s.message_count > 0 && (s.message_start_time != counted.message_start_time ||
                              s.message_end_time != counted.message_end_time)) {
    return "time span";
  }
  if (summary.chunk_indexes.size() != data.chunk_count) return "chunk index count";
  if (summary.channels.size() != data.channels.size()) return "channel count";
  for (const Channel& channel : summary.channels) {
    const auto found = data.channels.find(channel.id);
    if (found == data.channels.end() || !(found->second == channel)) return "channel records";
  }
  return "agrees";
}

}  // namespace

nlohmann::json mcap_info(const McapReader& reader) {
  Statistics counted;
  const DataSection data =
      reader.read([&](const Channel&, const Message& message) { counted.count(message); });

  nlohmann::json channels = nlohmann::json::array();
  for (const auto& [id, channel] : data.channels) {
    const auto schema = data.schemas.find(channel.schema_id);
    const auto count = counted.channel_message_counts.find(id);
    channels.push_back(
        {{"id", id},
         {"topic", channel.topic},
         {"schema", schema == data.schemas.end() ? "" : schema->second.name},
         {"message_encoding", channel.message_encoding},
         {"messages", count == counted.channel_message_counts.end() ? 0 : count->second}});
  }
  nlohmann::json attachments = nlohmann::json::array();
  for (const Attachment& a : data.attachments) {
    attachments.push_back(
        {{"name", a.name}, {"media_type", a.media_type}, {"bytes", a.data.bytes.size()}});
  }
  nlohmann::json metadata = nlohmann::json::array();
  for (const Metadata& m : data.metadata)
    metadata.push_back({{"name", m.name}, {"values", m.metadata}});
  return {{"library", reader.header().library},
          {"profile", reader.header().profile},
          {"closed", reader.closed()},
          {"complete", data.complete},
          {"cut", data.cut},
          {"messages", counted.message_count},
          {"chunks", data.chunk_count},
          {"compressions", data.compressions},
          {"start_ns", counted.message_start_time},
          {"end_ns", counted.message_end_time},
          {"channels", channels},
          {"attachments", attachments},
          {"metadata", metadata},
          {"summary", reader.summary() ? check_summary(*reader.summary(), data, counted) : "none"}};
}

}  // namespace ballsight::mcap
