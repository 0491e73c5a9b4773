#pragma once
// Records a running court service into MCAP files that Foxglove (or Lichtblick) opens: every
// navigation update the hub publishes, with the frames and detections of the frame set behind it.
// It listens to the hub like any client: the publishing thread only copies references (the frames
// are shared, never written after capture) into a bounded queue; a thread of the recorder's own
// encodes (JPEG, JSON) and writes. When the queue is full the update is dropped and counted, never
// waited for; a write that fails (a full disk) ends the recording with its error, and the service
// goes on. The service's health is recorded once a second, the clients' reports when they change.
// docs/recording.md lists the topics.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ballsight/record/compression.hpp"
#include "ballsight/service/camera_view.hpp"
#include "ballsight/service/court_service.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/service/run_file.hpp"

namespace ballsight {

struct RecordOptions {
  std::filesystem::path path;
  mcap::Compression compression = mcap::Compression::zstd;
  /// The frames of every Nth frame set are recorded (0: none); updates always.
  int frame_every = 1;
  /// A file that reaches this size is closed and the next one begun (0: no limit): FILE.mcap,
  /// then FILE-2.mcap, FILE-3.mcap, ...
  double max_mb = 0.0;
  FrameEncoding frames = FrameEncoding::jpeg;
  int jpeg_quality = 85;
  /// Updates waiting to be written; more are dropped (counted).
  std::size_t queue = 8;
  /// Instead of dropping, the publishing thread waits for room: nothing is lost and the service
  /// runs at the writer's pace. For an evaluation in simulated time (a lossless recording to
  /// replay), never for a live court.
  bool wait_for_room = false;

  /// Throws InputError naming the option for a value out of range.
  void validate() const;
};

/// What the recorder did so far.
struct RecorderCounts {
  std::uint64_t updates = 0;     // navigation updates written
  std::uint64_t frame_sets = 0;  // frame sets whose frames were written
  std::uint64_t dropped = 0;     // updates dropped: the queue was full
  std::uint64_t files = 0;       // files begun
  std::uint64_t bytes = 0;       // written to all of them
  std::string error;             // why recording stopped early ("" while it goes on)
};

class RunRecorder {
 public:
  /// Records `service`'s updates in `hub` from now on. Throws InputError naming the path when
  /// the first file cannot be created.
  RunRecorder(NavigationHub& hub, const CourtService& service, RecordOptions options);
  /// Stops listening, writes what is queued and closes the file: the final counts. Idempotent.
  RecorderCounts finish();
  /// Finishes.
  ~RunRecorder();
  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  RecorderCounts counts() const;

 private:
  struct Job {
    NavigationUpdate update;
    std::vector<CameraView> views;  // the frame set's, when its frames are recorded
  };
  void on_published(std::uint64_t seq);
  void run();
  void write(const Job& job);
  void begin_file();  // closes the current file, if any, once the next one is begun

  NavigationHub& hub_;
  const CourtService& service_;
  const RecordOptions options_;
  // The writer thread's after the constructor: described again, and a file begun, when the
  // service's pipeline is replaced (a camera re-calibrated).
  RunDescription run_;
  std::uint64_t generation_ = 0;  // the service's pipeline generation run_ describes

  mutable std::mutex mutex_;  // guards the queue, the counts and stopping_
  std::condition_variable wake_;
  std::condition_variable room_;  // the writer took an update from the queue
  std::deque<Job> queue_;
  RecorderCounts counts_;
  bool stopping_ = false;
  std::int64_t last_capture_ns_ = 0;   // of the last update queued
  std::uint64_t frame_sets_seen_ = 0;  // the frames of every Nth are recorded

  // The writer thread's own.
  std::unique_ptr<RunFile> file_;
  std::uint64_t files_begun_ = 0;
  std::uint64_t updates_in_file_ = 0;
  std::uint64_t bytes_closed_ = 0;       // in the files before this one
  std::uint64_t dropped_recorded_ = 0;   // the drops the last /recorder message told
  std::string reports_recorded_;         // the last /robot/reports message in this file
  std::int64_t health_recorded_ns_ = 0;  // the last /health message's time in this file

  int listener_ = 0;
  std::thread thread_;
};

}  // namespace ballsight
