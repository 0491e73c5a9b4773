// A camera calibration file (docs/site-file.md) through the project's reader.

#include "ballsight/camera/camera_file.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(data, size, [](std::string_view bytes) {
    ballsight::parse_camera_file(bytes, "camera.yml");
  });
}
