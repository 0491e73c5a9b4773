// A ball verifier's model (`eval detect-real --verifier`, detect/ball_verifier.hpp), loaded as
// BallVerifier::read does: OpenCV's ONNX importer, then a probe batch through the network.

#include "ballsight/detect/ball_verifier.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    ballsight::BallVerifier verifier(bytes, "verifier.onnx");
  });
}
