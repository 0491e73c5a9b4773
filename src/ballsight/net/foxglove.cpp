#include "ballsight/net/foxglove.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/csv_fields.hpp"
#include "ballsight/pipeline/route_json.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

// --- JSON Schemas of the foxglove.* messages sent (the fields ballsight fills) ---

json object_schema(const json& properties) {
  return {{"type", "object"}, {"properties", properties}};
}

json array_of(const json& items) {
  return {{"type", "array"}, {"items", items}};
}

const json kNumber{{"type", "number"}};

json time_schema() {
  return object_schema({{"sec", {{"type", "integer"}}}, {"nsec", {{"type", "integer"}}}});
}

json pose_schema() {
  return object_schema(
      {{"position", object_schema({{"x", kNumber}, {"y", kNumber}, {"z", kNumber}})},
       {"orientation",
        object_schema({{"x", kNumber}, {"y", kNumber}, {"z", kNumber}, {"w", kNumber}})}});
}

json color_schema() {
  return object_schema({{"r", kNumber}, {"g", kNumber}, {"b", kNumber}, {"a", kNumber}});
}

json scene_update_schema() {
  const json vector3 = object_schema({{"x", kNumber}, {"y", kNumber}, {"z", kNumber}});
  const json shape =
      object_schema({{"pose", pose_schema()}, {"size", vector3}, {"color", color_schema()}});
  const json line = object_schema({{"type", {{"type", "integer"}}},
                                   {"pose", pose_schema()},
                                   {"thickness", kNumber},
                                   {"scale_invariant", {{"type", "boolean"}}},
                                   {"points", array_of(vector3)},
                                   {"color", color_schema()}});
  const json entity = object_schema({{"timestamp", time_schema()},
                                     {"frame_id", {{"type", "string"}}},
                                     {"id", {{"type", "string"}}},
                                     {"lifetime", time_schema()},
                                     {"frame_locked", {{"type", "boolean"}}},
                                     {"spheres", array_of(shape)},
                                     {"cubes", array_of(shape)},
                                     {"lines", array_of(line)}});
  return object_schema({{"deletions", array_of(object_schema({{"id", {{"type", "string"}}}}))},
                        {"entities", array_of(entity)}});
}

struct Channel {
  std::uint32_t id;
  const char* topic;
  const char* schema_name;
  json schema;
};

enum ChannelId : std::uint32_t { kCourt = 1, kBalls, kRobot, kRoute, kNavigation };

const std::vector<Channel>& channels() {
  static const std::vector<Channel> kChannels{
      {kCourt, "/court", "foxglove.SceneUpdate", scene_update_schema()},
      {kBalls, "/balls", "foxglove.SceneUpdate", scene_update_schema()},
      {kRobot, "/robot_pose", "foxglove.PoseInFrame",
       object_schema({{"timestamp", time_schema()},
                      {"frame_id", {{"type", "string"}}},
                      {"pose", pose_schema()}})},
      {kRoute, "/route", "foxglove.PosesInFrame",
       object_schema({{"timestamp", time_schema()},
                      {"frame_id", {{"type", "string"}}},
                      {"poses", array_of(pose_schema())}})},
      {kNavigation, "/navigation", "ballsight.NavigationUpdate",
       object_schema({{"seq", {{"type", "integer"}}},
                      {"service_id", {{"type", "string"}}},
                      {"capture_time_ns", {{"type", "integer"}}},
                      {"published_ns", {{"type", "integer"}}},
                      {"world", {{"type", "object"}}},
                      {"route", {{"type", "object"}}}})},
  };
  return kChannels;
}

// --- Messages ---

constexpr const char* kFrame = "court";

json stamp(std::int64_t ns) {
  return {{"sec", ns / 1'000'000'000}, {"nsec", ns % 1'000'000'000}};
}

json point(double x, double y, double z = 0.0) {
  return {{"x", x}, {"y", y}, {"z", z}};
}

/// A pose at (x, y, z) heading `yaw` about the vertical.
json pose(double x, double y, double z, double yaw) {
  return {{"position", point(x, y, z)},
          {"orientation",
           {{"x", 0.0}, {"y", 0.0}, {"z", std::sin(yaw / 2.0)}, {"w", std::cos(yaw / 2.0)}}}};
}

json color(double r, double g, double b, double a = 1.0) {
  return {{"r", r}, {"g", g}, {"b", b}, {"a", a}};
}

json line(int type, const std::vector<Vec2>& points, double thickness, const json& rgba) {
  json pts = json::array();
  for (const Vec2& p : points) pts.push_back(point(p.x(), p.y()));
  return {{"type", type},
          {"pose", pose(0, 0, 0, 0)},
          {"thickness", thickness},
          {"scale_invariant", false},
          {"points", pts},
          {"color", rgba},
          {"colors", json::array()},
          {"indices", json::array()}};
}

json entity(const std::string& id, std::int64_t time_ns) {
  json e{{"timestamp", stamp(time_ns)}, {"frame_id", kFrame},    {"id", id},
         {"lifetime", stamp(0)},        {"frame_locked", false}, {"metadata", json::array()}};
  for (const char* kind :
       {"arrows", "cubes", "spheres", "cylinders", "lines", "triangles", "texts", "models"}) {
    e[kind] = json::array();
  }
  return e;
}

std::vector<Vec2> rectangle(double length, double width) {
  const double x = length / 2.0, y = width / 2.0;
  return {{-x, -y}, {x, -y}, {x, y}, {-x, y}};
}

json court_scene(const ApiContext& c, std::int64_t time_ns) {
  json e = entity("court", time_ns);
  constexpr int kLineLoop = 1, kLineList = 2;
  e["lines"].push_back(line(kLineLoop, rectangle(c.court.area_length_m, c.court.area_width_m), 0.05,
                            color(0.6, 0.6, 0.6)));
  e["lines"].push_back(
      line(kLineLoop, rectangle(c.court.length_m, c.court.width_m), 0.05, color(1, 1, 1)));
  if (c.court.net) {
    const double y = c.court.width_m / 2.0 + c.court.net_posts_outside_m;
    e["lines"].push_back(line(kLineList, {{0.0, -y}, {0.0, y}}, 0.08, color(0.1, 0.1, 0.1)));
  }
  return {{"deletions", json::array()}, {"entities", {e}}};
}

json balls_scene(const ApiContext& c, const NavigationUpdate& u) {
  json e = entity("balls", u.capture_time_ns);
  const double d = 2.0 * c.ball_radius_m;
  for (const FusedBall& b : u.world.balls) {
    e["spheres"].push_back({{"pose", pose(b.position_m.x(), b.position_m.y(), c.ball_radius_m, 0)},
                            {"size", point(d, d, d)},
                            {"color", color(0.8, 1.0, 0.1)}});
  }
  return {{"deletions", json::array()}, {"entities", {e}}};
}

json route_poses(const NavigationUpdate& u) {
  json poses = json::array();
  const std::vector<Vec2>& w = u.route.waypoints_m;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Vec2 along = i + 1 < w.size() ? Vec2(w[i + 1] - w[i])
                       : i > 0          ? Vec2(w[i] - w[i - 1])
                                        : Vec2(1, 0);
    poses.push_back(pose(w[i].x(), w[i].y(), 0.0, std::atan2(along.y(), along.x())));
  }
  return poses;
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
      return json_text(court_scene(context_, u.capture_time_ns));
    case kBalls:
      return json_text(balls_scene(context_, u));
    case kRobot:
      if (!u.world.robot) return std::nullopt;
      return json_text(
          {{"timestamp", stamp(u.capture_time_ns)},
           {"frame_id", kFrame},
           {"pose", pose(u.world.robot->pose.position.x(), u.world.robot->pose.position.y(), 0.0,
                         u.world.robot->pose.heading_rad)}});
    case kRoute:
      return json_text({{"timestamp", stamp(u.capture_time_ns)},
                        {"frame_id", kFrame},
                        {"poses", route_poses(u)}});
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
        out.binary.push_back(foxglove_message_frame(id, static_cast<std::uint64_t>(now),
                                                    json_text(court_scene(context_, now))));
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
