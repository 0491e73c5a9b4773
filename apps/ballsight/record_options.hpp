#pragma once
// The recording options of the commands that run a court service (`serve`): --record FILE.mcap
// and how (service/run_recorder.hpp).

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "ballsight/service/run_recorder.hpp"

namespace ballsight::app {

struct RecordArgs {
  std::string path;  // "": no recording
  std::string compression = "zstd";
  std::string frames = "jpeg";
  RecordOptions options;
};

void add_record_options(CLI::App& command, RecordArgs& args);

/// The recorder's options, checked (InputError naming the option); nothing without --record.
std::optional<RecordOptions> record_options(const RecordArgs& args);

/// Starts recording `service`'s updates in `hub` when --record was given (else nullptr).
std::unique_ptr<RunRecorder> start_recording(const RecordArgs& args, NavigationHub& hub,
                                             const CourtService& service);
/// Finishes a recording (if any) and says on one line, after `command`, what it holds.
void finish_recording(RunRecorder* recorder, const RecordArgs& args, const std::string& command);

}  // namespace ballsight::app
