// A site file (docs/site-file.md), as every court command reads it.

#include "ballsight/world/site.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ballsight::fuzz::parse_or_refuse(
      data, size, [](std::string_view bytes) { ballsight::parse_site(bytes, "site.yml"); });
}
