#pragma once
// The Foxglove WebSocket protocol, so that Foxglove and Lichtblick can open ws://HOST:PORT and
// show the court, the balls, the robot and its route live (../shared/research/net-web.md,
// section 2). The protocol was published as "foxglove.websocket.v1"; newer Foxglove speaks
// "foxglove.sdk.v1", which is the same under a new name, so both are accepted. Independent of
// the transport: text messages are JSON, message data is the binary frame
// 0x01 | u32 subscription id | u64 time (ns) | payload, integers little-endian. Channels are JSON
// with JSON Schema, under the foxglove.* schema names the 3D panel knows.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/net/api.hpp"

namespace ballsight {

/// The subprotocol to accept for a Sec-WebSocket-Protocol offer: "foxglove.sdk.v1" when offered,
/// else "foxglove.websocket.v1" when offered, else "" (not a Foxglove client).
std::string foxglove_subprotocol(std::string_view offered);

/// What goes back to one client: text (JSON) and binary (message data) frames, in this order.
struct FoxgloveOutput {
  std::vector<std::string> text;
  std::vector<std::string> binary;
};

/// One connected Foxglove client: its subscriptions and what it is sent.
class FoxgloveSession {
 public:
  explicit FoxgloveSession(const ApiContext& context);

  /// serverInfo, then the advertisement of every channel.
  std::vector<std::string> greeting() const;
  /// A text message of the client (subscribe, unsubscribe). A bad one is answered with a status
  /// message (level error) and changes nothing; a new subscription gets the latest value at once.
  FoxgloveOutput on_text(std::string_view message, const std::optional<NavigationUpdate>& latest);
  /// Message data of `update` for every subscription.
  std::vector<std::string> frames(const NavigationUpdate& update) const;

  std::size_t subscriptions() const { return channel_of_.size(); }
  /// Each subscription costs a payload per update on the I/O thread: a client gets this many.
  static constexpr std::size_t kMaxSubscriptions = 32;

 private:
  std::optional<std::string> payload(std::uint32_t channel, const NavigationUpdate& update) const;

  const ApiContext& context_;
  std::map<std::uint32_t, std::uint32_t> channel_of_;  // subscription id -> channel id
};

/// The binary message-data frame: 0x01, subscription id, time, payload.
std::string foxglove_message_frame(std::uint32_t subscription, std::uint64_t time_ns,
                                   std::string_view payload);

}  // namespace ballsight
