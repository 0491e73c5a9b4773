// A calibration sample CSV (`omni fit --samples`, docs/omni-calibration.md).

#include "ballsight/calib/sample_csv.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    ballsight::parse_polar_samples_csv(bytes, "samples.csv");
  });
}
