#include "ballsight/net/foxglove.hpp"

#include <algorithm>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/service/foxglove_messages.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

struct Channel {
  std::uint32_t id;
  const char* topic;
  const char* schema_name;
  json schema;
};

enum ChannelId : std::uint32_t { kCourt = 1, kBalls, kRobot, kRoute, kNavigation };

const std::vector<Channel>& channels() {
  static const std::vector<Channel> kChannels{
      {kCourt, "/court", "foxglove.SceneUpdate", foxglove::scene_update_schema()},
      {kBalls, "/balls", "foxglove.SceneUpdate", foxglove::scene_update_schema()},
      {kRobot, "/robot_pose", "foxglove.PoseInFrame", foxglove::pose_in_frame_schema()},
      {kRoute, "/route", "foxglove.PosesInFrame", foxglove::poses_in_frame_schema()},
      {kNavigation, "/navigation", "ballsight.NavigationUpdate",
       foxglove::navigation_update_schema()},
  };
  return kChannels;
}

}  // namespace

std::string foxglove_subprotocol(std::string_view offered) {
  const std::vector<CsvField> tokens = split_csv_fields(offered);  // a comma-separated list
  for (const char* name : {"foxglove.sdk.v1", "foxglove.websocket.v1"}) {
    if (std::any_of(tokens.begin(), tokens.end(),
                    [&](const CsvField& t) { return t.text == name; })) {
      return name;
    }
  }
  return "";
}

std::string foxglove_message_frame(std::uint32_t subscription, std::uint64_t time_ns,
                                   std::string_view payload) {
  std::string frame(13, '\0');
  frame[0] = 0x01;
  for (int i = 0; i < 4; ++i) frame[1 + i] = static_cast<char>((subscription >> (8 * i)) & 0xff);
  for (int i = 0; i < 8; ++i) frame[5 + i] = static_cast<char>((time_ns >> (8 * i)) & 0xff);
  frame.append(payload);
  return frame;
}

FoxgloveSession::FoxgloveSession(const ApiContext& context) : context_(context) {}

std::vector<std::string> FoxgloveSession::greeting() const {
  json list = json::array();
  for (const Channel& ch : channels()) {
    list.push_back({{"id", ch.id},
                    {"topic", ch.topic},
                    {"encoding", "json"},
                    {"schemaName", ch.schema_name},
                    {"schema", ch.schema.dump()},
                    {"schemaEncoding", "jsonschema"}});
  }
  return {json{{"op", "serverInfo"},
               {"name", "ballsight"},
               {"capabilities", json::array()},
               {"supportedEncodings", json::array()},
               {"metadata", json::object()},
               {"sessionId", context_.hub.service_id()}}
              .dump(),
          json{{"op", "advertise"}, {"channels", list}}.dump()};
}

std::optional<std::string> FoxgloveSession::payload(std::uint32_t channel,
                                                    const NavigationUpdate& u) const {
  switch (channel) {
    case kCourt:
      return json_text(foxglove::court_scene(context_.court, u.capture_time_ns));
    case kBalls:
      return json_text(foxglove::balls_scene(u.world, context_.ball_radius_m, u.capture_time_ns));
    case kRobot: {
      const std::optional<json> robot = foxglove::robot_pose(u.world, u.capture_time_ns);
      if (!robot) return std::nullopt;
      return json_text(*robot);
    }
    case kRoute:
      return json_text(foxglove::route_poses(u.route, u.capture_time_ns));
    default:
      return json_text(navigation_json(u, context_));
  }
}

FoxgloveOutput FoxgloveSession::on_text(std::string_view message,
                                        const std::optional<NavigationUpdate>& latest) {
  FoxgloveOutput out;
  const auto status = [&](const std::string& what) {
    out.text.push_back(json_text({{"op", "status"}, {"level", 2}, {"message", what}}));
    return out;
  };
  const json m = json::parse(message, nullptr, false);
  if (m.is_discarded() || !m.is_object()) return status("expected a JSON object");
  const auto op = m.find("op");
  if (op == m.end() || !op->is_string()) return status("expected a string 'op'");
  const auto id_of = [](const json& v) -> std::optional<std::uint32_t> {
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() > 0xffffffffu) return std::nullopt;
    return v.get<std::uint32_t>();
  };
  if (*op == "subscribe") {
    const auto subs = m.find("subscriptions");
    if (subs == m.end() || !subs->is_array()) return status("subscribe: expected 'subscriptions'");
    std::map<std::uint32_t, std::uint32_t> added;
    for (const json& s : *subs) {
      if (!s.is_object() || !s.contains("id") || !s.contains("channelId")) {
        return status("subscribe: each subscription needs 'id' and 'channelId'");
      }
      const std::optional<std::uint32_t> id = id_of(s["id"]), channel = id_of(s["channelId"]);
      if (!id || !channel || *channel < kCourt || *channel > kNavigation) {
        return status("subscribe: unknown channel or bad id");
      }
      if (channel_of_.size() + added.size() >= kMaxSubscriptions) {
        return status("subscribe: at most " + std::to_string(kMaxSubscriptions) +
                      " subscriptions per client");
      }
      if (channel_of_.count(*id) || added.count(*id)) {
        return status("subscribe: subscription id " + std::to_string(*id) + " is taken");
      }
      added[*id] = *channel;
    }
    for (const auto& [id, channel] : added) {
      channel_of_[id] = channel;
      const std::int64_t now = utc_now_ns();
      if (channel == kCourt) {
        out.binary.push_back(
            foxglove_message_frame(id, static_cast<std::uint64_t>(now),
                                   json_text(foxglove::court_scene(context_.court, now))));
      } else if (latest) {
        if (const std::optional<std::string> p = payload(channel, *latest)) {
          out.binary.push_back(
              foxglove_message_frame(id, static_cast<std::uint64_t>(latest->capture_time_ns), *p));
        }
      }
    }
    return out;
  }
  if (*op == "unsubscribe") {
    const auto ids = m.find("subscriptionIds");
    if (ids == m.end() || !ids->is_array())
      return status("unsubscribe: expected 'subscriptionIds'");
    for (const json& v : *ids) {
      if (const std::optional<std::uint32_t> id = id_of(v)) channel_of_.erase(*id);
    }
    return out;
  }
  return status("unsupported op '" + op->get<std::string>() + "'");
}

std::vector<std::string> FoxgloveSession::frames(const NavigationUpdate& update) const {
  std::vector<std::string> out;
  for (const auto& [id, channel] : channel_of_) {
    if (channel == kCourt) continue;  // sent once, at subscription
    if (const std::optional<std::string> p = payload(channel, update)) {
      out.push_back(
          foxglove_message_frame(id, static_cast<std::uint64_t>(update.capture_time_ns), *p));
    }
  }
  return out;
}

}  // namespace ballsight
