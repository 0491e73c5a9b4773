// The Foxglove WebSocket protocol: the offer is negotiated, channels advertised with JSON Schema,
// subscriptions answered with message data in the binary layout the protocol fixes, bad client
// messages answered with a status and nothing else. Over a real socket at the end.
#include "ballsight/net/foxglove.hpp"

#include <gtest/gtest.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include "ballsight/net/api.hpp"
#include "ballsight/net/http_server.hpp"
#include "sample_update.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

NavigationUpdate update() {
  return test::sample_update({Vec2(1.0, 2.0), 0.5}, 1'700'000'000'123'456'789);
}

std::uint64_t little_endian(const std::string& bytes, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

/// channel topic -> id, from the advertisement.
std::map<std::string, std::uint32_t> advertised(const FoxgloveSession& session) {
  const std::vector<std::string> greeting = session.greeting();
  EXPECT_EQ(greeting.size(), 2u);
  EXPECT_EQ(json::parse(greeting[0])["op"], "serverInfo");
  const json advertise = json::parse(greeting[1]);
  EXPECT_EQ(advertise["op"], "advertise");
  std::map<std::string, std::uint32_t> ids;
  for (const json& ch : advertise["channels"]) {
    EXPECT_EQ(ch["encoding"], "json");
    EXPECT_EQ(ch["schemaEncoding"], "jsonschema");
    EXPECT_TRUE(json::parse(ch["schema"].get<std::string>()).is_object());
    ids[ch["topic"]] = ch["id"];
  }
  return ids;
}

TEST(Foxglove, SubprotocolOffersAreNegotiated) {
  EXPECT_EQ(foxglove_subprotocol("foxglove.websocket.v1"), "foxglove.websocket.v1");
  EXPECT_EQ(foxglove_subprotocol("foxglove.websocket.v1, foxglove.sdk.v1"), "foxglove.sdk.v1");
  EXPECT_EQ(foxglove_subprotocol("chat,superchat"), "");
  EXPECT_EQ(foxglove_subprotocol("foxglove.sdk.v10"), "");
}

TEST(Foxglove, SubscriptionsGetMessageDataInTheProtocolsLayout) {
  NavigationHub hub;
  ApiContext context{hub, {"ne"}, SiteCourt{}, 0.0335};
  FoxgloveSession session(context);
  const auto ids = advertised(session);
  ASSERT_EQ(ids.size(), 5u);
  const json subscribe{{"op", "subscribe"},
                       {"subscriptions",
                        {{{"id", 7}, {"channelId", ids.at("/robot_pose")}},
                         {{"id", 8}, {"channelId", ids.at("/court")}}}}};
  const FoxgloveOutput out = session.on_text(subscribe.dump(), update());
  EXPECT_TRUE(out.text.empty());
  ASSERT_EQ(out.binary.size(), 2u);  // the latest pose and the court, at once
  const std::vector<std::string> frames = session.frames(update());
  ASSERT_EQ(frames.size(), 1u);  // the court is not sent again
  const std::string& f = frames[0];
  EXPECT_EQ(f[0], 0x01);
  EXPECT_EQ(little_endian(f, 1, 4), 7u);
  EXPECT_EQ(little_endian(f, 5, 8), 1'700'000'000'123'456'789u);
  const json pose = json::parse(f.substr(13));
  EXPECT_EQ(pose["frame_id"], "court");
  EXPECT_EQ(pose["timestamp"]["sec"], 1'700'000'000);
  EXPECT_EQ(pose["timestamp"]["nsec"], 123'456'789);
  EXPECT_DOUBLE_EQ(pose["pose"]["position"]["x"], 1.0);
  EXPECT_NEAR(pose["pose"]["orientation"]["z"], std::sin(0.25), 1e-12);
  session.on_text(R"({"op": "unsubscribe", "subscriptionIds": [7]})", std::nullopt);
  EXPECT_TRUE(session.frames(update()).empty());
}

TEST(Foxglove, BadClientMessagesGetAStatusAndChangeNothing) {
  NavigationHub hub;
  ApiContext context{hub, {"ne"}, SiteCourt{}, 0.0335};
  FoxgloveSession session(context);
  for (
      const char* bad :
      {"not json", "[1]", R"({"op": 3})", R"({"op": "subscribe"})",
       R"({"op": "subscribe", "subscriptions": [{"id": 1, "channelId": 99}]})",
       R"({"op": "subscribe", "subscriptions": [{"id": -1, "channelId": 1}]})",
       R"({"op": "subscribe", "subscriptions": [{"id": 1, "channelId": 2}, {"id": 1, "channelId": 3}]})",
       R"({"op": "advertise", "channels": []})"}) {
    const FoxgloveOutput out = session.on_text(bad, update());
    ASSERT_EQ(out.text.size(), 1u) << bad;
    EXPECT_EQ(json::parse(out.text[0])["op"], "status") << bad;
    EXPECT_EQ(json::parse(out.text[0])["level"], 2) << bad;
    EXPECT_EQ(session.subscriptions(), 0u) << bad;
  }
}

TEST(Foxglove, TheServiceSpeaksItOnItsOwnPort) {
  namespace asio = boost::asio;
  namespace beast = boost::beast;
  namespace websocket = beast::websocket;
  NavigationHub hub;
  ApiContext context{hub, {"ne"}, SiteCourt{}, 0.0335};
  HttpServerOptions options;
  options.port = 0;
  options.token = "0123456789abcdef0123";
  HttpServer server(options, api_v1_routes(context));
  asio::io_context io;
  websocket::stream<asio::ip::tcp::socket> ws(io);
  ws.next_layer().connect({asio::ip::make_address("127.0.0.1"), server.port()});
  ws.set_option(websocket::stream_base::decorator([](websocket::request_type& req) {
    req.set(beast::http::field::sec_websocket_protocol, "foxglove.websocket.v1");
  }));
  websocket::response_type answer;
  ws.handshake(answer, "127.0.0.1", "/");
  EXPECT_EQ(answer[beast::http::field::sec_websocket_protocol], "foxglove.websocket.v1");
  beast::flat_buffer buffer;
  ws.read(buffer);
  EXPECT_EQ(json::parse(beast::buffers_to_string(buffer.data()))["op"], "serverInfo");
  buffer.consume(buffer.size());
  ws.read(buffer);
  const json advertise = json::parse(beast::buffers_to_string(buffer.data()));
  buffer.consume(buffer.size());
  std::uint32_t balls = 0;
  for (const json& ch : advertise["channels"])
    if (ch["topic"] == "/balls") balls = ch["id"];
  ws.write(asio::buffer(
      json{{"op", "subscribe"}, {"subscriptions", {{{"id", 3}, {"channelId", balls}}}}}.dump()));
  hub.publish(update());
  ws.read(buffer);
  EXPECT_TRUE(ws.got_binary());
  const std::string frame = beast::buffers_to_string(buffer.data());
  EXPECT_EQ(little_endian(frame, 1, 4), 3u);
  const json scene = json::parse(frame.substr(13));
  EXPECT_EQ(scene["entities"][0]["spheres"].size(), 1u);
}

}  // namespace
}  // namespace ballsight
