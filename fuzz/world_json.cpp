// A world model JSON (`plan --world`), as the planner reads it.

#include "ballsight/pipeline/planning_input.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    ballsight::parse_world_balls(bytes, "world.json");
  });
}
