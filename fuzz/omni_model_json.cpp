// A fitted omni model (`omni fit --model-out`), parsed as load_omni_model does.

#include <nlohmann/json.hpp>

#include "ballsight/calib/model_json.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    const nlohmann::json document = nlohmann::json::parse(bytes, nullptr, false);
    if (!document.is_discarded()) ballsight::omni_model_from_json(document, "model.json");
  });
}
