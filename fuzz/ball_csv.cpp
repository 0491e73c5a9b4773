// A CSV of ball positions (`plan --balls`).

#include "ballsight/pipeline/planning_input.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(
      data, size, [](std::string_view bytes) { ballsight::parse_ball_csv(bytes, "balls.csv"); });
}
