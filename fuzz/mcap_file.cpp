// An MCAP recording (`record info`): the summary through the footer, then every
// record of the data section, chunks decompressed (at most 16 MB each here).

#include "ballsight/record/mcap_reader.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    const ballsight::mcap::McapReader reader(bytes, "run.mcap", {std::uint64_t{1} << 24});
    reader.read([](const ballsight::mcap::Channel&, const ballsight::mcap::Message&) {});
  });
}
