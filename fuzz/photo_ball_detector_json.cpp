// The photo detector's settings (`detect fit --out`, `detect balls --detector`), parsed as
// read_photo_ball_options does.

#include <nlohmann/json.hpp>

#include "ballsight/detect/photo_ball_fit.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    const nlohmann::json document = nlohmann::json::parse(bytes, nullptr, false);
    if (!document.is_discarded())
      ballsight::photo_ball_options_from_json(document, "detector.json");
  });
}
