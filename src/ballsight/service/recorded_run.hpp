#pragma once
// A recorded run read back (docs/recording.md, "Replay"): its setup (run_setup.hpp) and, update by
// update in the order they were published, the navigation update as recorded, the reports it was
// planned with and the frames of its frame set, decoded. What `eval replay` compares and
// `serve --replay` serves.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ballsight/pipeline/frame_set.hpp"
#include "ballsight/record/mcap_reader.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/service/run_setup.hpp"

namespace ballsight {

struct RecordedUpdate {
  std::uint64_t seq = 0;
  std::int64_t capture_time_ns = 0;
  std::int64_t published_ns = 0;
  nlohmann::json navigation;  // /navigation as recorded (navigation_json)
  /// The reports it was planned with (/robot/reports are recorded when they change).
  ClientReports reports;
  /// Its frame set's frames, one per camera (an empty image: none from that camera), when they
  /// were recorded; empty when the update re-planned the previous world (no new frames) or its
  /// frames were not recorded (--record-every).
  FrameSet frames;
  /// A new frame set (its capture time differs from the previous update's).
  bool new_frame_set = false;
  /// The last update of a file cut short (its writer killed): some of its messages may be lost.
  bool cut_short = false;
};

class RecordedRun {
 public:
  /// Opens a recording and reads its setup; throws InputError naming the file (and what is wrong
  /// or missing in it).
  explicit RecordedRun(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  const RunSetup& setup() const { return setup_; }
  const std::vector<std::string>& camera_names() const { return camera_names_; }
  /// The frames' encoding as recorded ("jpeg" or "png").
  const std::string& frames() const { return frames_; }
  /// Why the file ends early ("" when it was closed properly): a run that was killed.
  const std::string& cut() const { return cut_; }

  /// Every update in publishing order, frames decoded as 8-bit BGR (of any size, which the
  /// pipeline judges as it did live); `on_update` returns false to stop. Throws InputError
  /// naming the file and the message for a message that does not read, and for what `on_update`
  /// finds malformed in an update (a nlohmann::json exception).
  void for_each_update(const std::function<bool(const RecordedUpdate&)>& on_update) const;

 private:
  std::filesystem::path path_;
  mcap::McapReader reader_;
  RunSetup setup_;
  std::vector<std::string> camera_names_;
  std::string frames_ = "jpeg";
  std::string cut_;
};

}  // namespace ballsight
