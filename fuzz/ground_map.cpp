// A ballsight lookup table (docs/lut-format.md), as `omni locate --lut` and the omni node load it.

#include "ballsight/camera/ground_map_io.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    ballsight::parse_ground_map(bytes, "table.lut", std::nullopt);
  });
}
