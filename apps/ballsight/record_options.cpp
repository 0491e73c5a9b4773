#include "record_options.hpp"

#include <iostream>

#include "ballsight/core/error.hpp"

namespace ballsight::app {

void add_record_options(CLI::App& command, RecordArgs& args) {
  command.add_option("--record", args.path,
                     "Record the run into this MCAP file (Foxglove opens it; docs/recording.md)");
  command
      .add_option("--record-every", args.options.frame_every,
                  "Record the camera frames of every Nth frame set (0: none; updates always)")
      ->capture_default_str();
  command
      .add_option("--record-max-mb", args.options.max_mb,
                  "Begin a new file (FILE-2.mcap, ...) when one reaches this size (0: no limit)")
      ->capture_default_str();
  command.add_option("--record-compression", args.compression, "zstd, lz4 or none")
      ->capture_default_str();
  command
      .add_option(
          "--record-frames", args.frames,
          "jpeg, or png: lossless, so that `eval replay` sees exactly the pipeline's frames")
      ->capture_default_str();
  command
      .add_option("--record-jpeg-quality", args.options.jpeg_quality,
                  "JPEG quality of the recorded frames, 1-100")
      ->capture_default_str();
}

std::optional<RecordOptions> record_options(const RecordArgs& args) {
  if (args.path.empty()) return std::nullopt;
  RecordOptions options = args.options;
  options.path = args.path;
  options.compression = mcap::parse_compression(args.compression, "--record-compression");
  require(args.frames == "jpeg" || args.frames == "png", "--record-frames",
          "expected jpeg or png, got '" + args.frames + "'");
  options.frames = args.frames == "png" ? FrameEncoding::png : FrameEncoding::jpeg;
  options.validate();
  return options;
}

std::unique_ptr<RunRecorder> start_recording(const RecordArgs& args, NavigationHub& hub,
                                             const CourtService& service) {
  const std::optional<RecordOptions> options = record_options(args);
  if (!options) return nullptr;
  return std::make_unique<RunRecorder>(hub, service, *options);
}

void finish_recording(RunRecorder* recorder, const RecordArgs& args, const std::string& command) {
  if (recorder == nullptr) return;
  const RecorderCounts c = recorder->finish();  // writes what is queued, closes the file
  std::cout << command << ": recorded " << c.updates << " updates (" << c.frame_sets
            << " frame sets with frames, " << c.dropped << " dropped) in " << c.files
            << " file(s) from " << args.path << ", " << c.bytes << " bytes"
            << (c.error.empty() ? "" : "; recording stopped: " + c.error) << std::endl;
}

}  // namespace ballsight::app
