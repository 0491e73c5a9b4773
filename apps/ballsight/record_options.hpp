#pragma once
// The recording options of the commands that run a court service (`serve`): --record FILE.mcap
// and how (service/run_recorder.hpp).

#include <CLI/CLI.hpp>
#include <string>

#include "ballsight/service/run_recorder.hpp"

namespace ballsight::app {

struct RecordArgs {
  std::string path;  // "": no recording
  std::string compression = "zstd";
  RecordOptions options;
};

void add_record_options(CLI::App& command, RecordArgs& args);

/// The recorder's options, checked (InputError naming the option); nothing without --record.
std::optional<RecordOptions> record_options(const RecordArgs& args);

}  // namespace ballsight::app
