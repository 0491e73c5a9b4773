#pragma once
// One MCAP file of a recorded run (docs/recording.md): what a file holds and how a navigation
// update and its frame set become its messages. The recorder (run_recorder.hpp) decides what goes
// in and when, on a thread of its own; this is the encoding (JPEG, JSON) and the writing.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ballsight/record/compression.hpp"
#include "ballsight/service/camera_view.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/service/run_setup.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

namespace mcap {
class McapWriter;
}

/// How a recording encodes the frames: JPEG (small; a replay sees slightly other frames than the
/// pipeline saw) or PNG (lossless: a replay sees exactly the pipeline's frames).
enum class FrameEncoding { jpeg, png };

/// What every file of a run says about it.
struct RunDescription {
  std::string service_id;
  std::vector<std::string> camera_names;
  /// The site (its files, when it has them, become attachments), the pipeline and the planner
  /// as the recording began: what a replay needs (run_setup.hpp).
  RunSetup setup;
  /// run_setup_attachments(setup): encoded once for all the run's files.
  std::vector<mcap::Attachment> setup_attachments;
  int frame_every = 1;
  mcap::Compression compression = mcap::Compression::zstd;
  FrameEncoding frames = FrameEncoding::jpeg;
  int jpeg_quality = 85;
};

/// Each camera's topic prefix, "/camera/NAME" with the name's letters, digits and '_' (others
/// become '_': "camera 0" -> "camera_0"), made unique by its index where two would be the same.
std::vector<std::string> camera_topics(const std::vector<std::string>& names);

class RunFile {
 public:
  /// Creates `path` (the run's file `number`, from 1) with its schemas, channels, metadata,
  /// attachments and the court. Throws InputError naming the path when it cannot be created.
  RunFile(const std::filesystem::path& path, const RunDescription& run, std::uint64_t number);
  ~RunFile();
  RunFile(const RunFile&) = delete;
  RunFile& operator=(const RunFile&) = delete;

  /// `update`, and the frames and detections of `views` (one per camera; an empty frame: none).
  /// Throws std::runtime_error naming the path when the disk refuses it.
  void write_update(const NavigationUpdate& update, const std::vector<CameraView>& views);
  /// What goes beside the updates, now and then: the recorder's counts (/recorder), what the
  /// robot and other clients reported (/robot/reports), the service's health (/health).
  enum class Side { recorder, reports, health };
  /// `message` on the side topic, at `update`'s publish time and with its seq.
  void write_side(Side topic, const NavigationUpdate& update, const nlohmann::json& message);
  /// Writes the summary and the footer (mcap::McapWriter::close).
  void close();
  /// Bytes so far (the open chunk's included).
  std::uint64_t size() const;

 private:
  void put(std::size_t channel, std::uint32_t seq, std::int64_t time_ns, std::int64_t publish_ns,
           const nlohmann::json& message);

  const RunDescription& run_;
  std::unique_ptr<mcap::McapWriter> writer_;
  std::vector<std::uint16_t> channels_;
};

}  // namespace ballsight
