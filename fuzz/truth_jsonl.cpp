// The simulated court's truth record (JSON lines of `serve --sim --truth-out`, read back by
// --resume).

#include <sstream>
#include <string>

#include "ballsight/service/loop_truth.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    std::istringstream in{std::string(bytes)};
    ballsight::parse_loop_truth(in, "truth.jsonl");
  });
}
