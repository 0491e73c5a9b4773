#pragma once
// What an MCAP file holds, read through (every chunk decompressed and its CRC checked): for
// `ballsight record info` and the tests.

#include <nlohmann/json.hpp>

#include "ballsight/record/mcap_reader.hpp"

namespace ballsight::mcap {

/// {"library", "profile", "closed", "complete", "cut", "messages", "chunks", "compressions",
/// "start_ns", "end_ns", "channels": [{"id", "topic", "schema", "message_encoding",
/// "messages"}], "attachments": [{"name", "media_type", "bytes"}], "metadata": [{"name",
/// "values"}], "summary": "agrees" | "none" | what disagrees}. The summary is checked against
/// what was read: its message, chunk and per-channel counts, its time span, its channels.
nlohmann::json mcap_info(const McapReader& reader);

}  // namespace ballsight::mcap
