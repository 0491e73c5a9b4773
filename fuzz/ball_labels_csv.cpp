// A labelled photo source's labels.csv (`eval detect-real`, `detect fit`), parsed as
// read_labelled_source does.

#include "ballsight/detect/ball_labels.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    ballsight::parse_ball_labels(bytes, "labels.csv");
  });
}
