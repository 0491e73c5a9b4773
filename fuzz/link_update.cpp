// What the robot's client parses from the network (net/robot_link.cpp): arbitrary JSON as a
// navigation update is either taken or refused with an InputError, never anything else.

#include <cstdint>
#include <string>

#include "ballsight/core/error.hpp"
#include "ballsight/net/http_robot_link.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const nlohmann::json j =
      nlohmann::json::parse(std::string(reinterpret_cast<const char*>(data), size), nullptr, false);
  if (j.is_discarded()) return 0;
  try {
    ballsight::parse_link_update(j);
  } catch (const ballsight::InputError&) {
  }
  return 0;
}
