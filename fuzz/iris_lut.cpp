// An IRIS int16 table (`omni inspect --iris`), either kind: the first byte picks it.

#include "ballsight/camera/iris_lut.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    if (bytes.empty()) return;
    const auto kind = bytes[0] % 2 ? ballsight::IrisLutKind::cm2px : ballsight::IrisLutKind::px2cm;
    ballsight::parse_iris_lut(bytes.substr(1), "table.bin", kind);
  });
}
