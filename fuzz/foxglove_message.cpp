// A Foxglove client's text messages (net/foxglove.cpp) on arbitrary input: the session must
// answer with JSON text and well-formed message data frames, and never throw.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "ballsight/net/foxglove.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ballsight;
  static NavigationHub hub;
  static const ApiContext context(hub, {"ne"}, SiteCourt{}, 0.0335);
  static FoxgloveSession session(context);  // subscriptions carry over between inputs
  NavigationUpdate u;
  u.capture_time_ns = 5;
  u.world.balls.push_back({Vec2(3, 4), Eigen::Matrix2d::Zero(), {0}});
  const FoxgloveOutput out =
      session.on_text(std::string(reinterpret_cast<const char*>(data), size), u);
  for (const std::string& text : out.text) {
    if (nlohmann::json::parse(text, nullptr, false).is_discarded()) std::abort();
  }
  for (const std::string& frame : out.binary) {
    if (frame.size() < 13 || frame[0] != 0x01) std::abort();
  }
  for (const std::string& frame : session.frames(u)) {
    if (frame.size() < 13 || frame[0] != 0x01) std::abort();
  }
  return 0;
}
