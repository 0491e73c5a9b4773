// `ballsight record info FILE.mcap`: what a recording holds, read through and checked (chunk
// CRCs, the summary against the data), and, for a file whose writer was stopped, how much of it
// is readable.

#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "ballsight/record/mcap_info.hpp"
#include "commands.hpp"

namespace ballsight::app {
namespace {

struct RecordInfoArgs {
  std::string file;
  bool json = false;
};

void print_info(const nlohmann::json& info) {
  const double seconds = (info["end_ns"].get<double>() - info["start_ns"].get<double>()) / 1e9;
  std::cout << "library: " << info["library"].get<std::string>() << "\n"
            << "messages: " << info["messages"] << " in " << info["chunks"] << " chunks ("
            << info["compressions"].dump() << "), " << std::fixed << std::setprecision(1) << seconds
            << " s\n"
            << "file: "
            << (info["closed"].get<bool>() ? "closed, summary " + info["summary"].get<std::string>()
                                           : "not closed: " + info["cut"].get<std::string>())
            << "\nchannels:\n";
  for (const auto& c : info["channels"]) {
    std::cout << "  " << std::setw(4) << c["id"].get<int>() << "  " << std::left << std::setw(32)
              << c["topic"].get<std::string>() << std::setw(28) << c["schema"].get<std::string>()
              << std::right << std::setw(8) << c["messages"] << "\n";
  }
  for (const auto& a : info["attachments"]) {
    std::cout << "attachment: " << a["name"].get<std::string>() << " ("
              << a["media_type"].get<std::string>() << ", " << a["bytes"] << " bytes)\n";
  }
  for (const auto& m : info["metadata"]) {
    std::cout << "metadata " << m["name"].get<std::string>() << ": " << m["values"].dump() << "\n";
  }
}

}  // namespace

void add_record_commands(CLI::App& app) {
  CLI::App* record = app.add_subcommand("record", "Recordings of runs (MCAP files)");
  record->require_subcommand(1);
  auto args = std::make_shared<RecordInfoArgs>();
  CLI::App* info = record->add_subcommand(
      "info",
      "What a recording holds: its channels, messages, attachments and metadata, every "
      "chunk read and checked (a file cut short is read up to its last complete record)");
  info->add_option("file", args->file, "The MCAP file")->required();
  info->add_flag("--json", args->json, "Print JSON");
  info->callback([args] {
    const nlohmann::json result = mcap::mcap_info(mcap::McapReader::open(args->file));
    if (args->json) {
      std::cout << result.dump(2) << "\n";
    } else {
      print_info(result);
    }
  });
}

}  // namespace ballsight::app
