// A ball colour model (`colours learn --out`, `detect balls --colours`), parsed as
// read_ball_colours does.

#include <nlohmann/json.hpp>

#include "ballsight/detect/ball_colours.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    const nlohmann::json document = nlohmann::json::parse(bytes, nullptr, false);
    if (!document.is_discarded()) ballsight::ball_colours_from_json(document, "colours.json");
  });
}
