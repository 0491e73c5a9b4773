// The navigation service over a real socket: a Beast client on 127.0.0.1, the server on a port
// it picks, stopped at the end of every test.
#include "ballsight/net/http_server.hpp"

#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <filesystem>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/net/api.hpp"
#include "ballsight/net/calibration/omni_calibration_api.hpp"
#include "sample_update.hpp"

namespace ballsight {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

constexpr const char* kToken = "0123456789abcdef0123";

/// API v1 and the omni calibration API (its routes run long) behind a server.
struct Service {
  NavigationHub hub;
  OmniCalibrationApi omni;
  ApiContext context{hub, {"ne"}, SiteCourt{}, 0.0335};
  HttpServer server;

  explicit Service(HttpServerOptions options = with_token()) : server(options, routes()) {}
  ApiRoutes routes() {
    ApiRoutes r = api_v1_routes(context);
    omni.register_routes(r);
    return r;
  }
  static HttpServerOptions with_token() {
    HttpServerOptions o;
    o.port = 0;
    o.token = kToken;
    return o;
  }
};

/// One connection to the service.
struct Client {
  asio::io_context io;
  tcp::socket socket{io};
  beast::flat_buffer buffer;

  explicit Client(unsigned short port) {
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  }
  http::response<http::string_body> send(http::verb verb, const std::string& target,
                                         const std::string& body = "", bool token = false) {
    http::request<http::string_body> req{verb, target, 11};
    req.set(http::field::host, "127.0.0.1");
    if (token) req.set(http::field::authorization, std::string("Bearer ") + kToken);
    req.body() = body;
    req.prepare_payload();
    http::write(socket, req);
    http::response<http::string_body> res;
    http::read(socket, buffer, res);
    return res;
  }
};

TEST(HttpServer, RoutesTokenAndKeepAlive) {
  Service service;
  Client client(service.server.port());
  EXPECT_EQ(client.send(http::verb::get, "/api/v1/health").result_int(), 200);
  const auto no_token =
      client.send(http::verb::put, "/api/v1/robot", R"({"x_m": 1, "y_m": 2, "heading_deg": 0})");
  EXPECT_EQ(no_token.result_int(), 401);
  EXPECT_NE(no_token.body().find("\"where\":\"headers\""), std::string::npos) << no_token.body();
  // The same connection goes on after a refused request.
  EXPECT_EQ(
      client
          .send(http::verb::put, "/api/v1/robot", R"({"x_m": 1, "y_m": 2, "heading_deg": 0})", true)
          .result_int(),
      200);
  EXPECT_EQ(client.send(http::verb::get, "/api/v1/robot").result_int(), 200);
  EXPECT_EQ(client.send(http::verb::get, "/nothing").result_int(), 404);
  EXPECT_EQ(service.server.connections(), 1);
}

TEST(HttpServer, EveryDocumentedRouteAnswersAsDocumentedOverTheWire) {
  Service service;
  service.hub.publish(test::sample_update({Vec2(1, 1), 0.0}));
  Client client(service.server.port());
  const nlohmann::json doc =
      nlohmann::json::parse(client.send(http::verb::get, "/api/v1/openapi.json").body());
  const auto verb_of = [](const std::string& method) { return http::string_to_verb(method); };
  int operations = 0;
  for (const auto& [path, item] : doc["paths"].items()) {
    for (const auto& [method, operation] : item.items()) {
      std::string upper = method;
      for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      for (const bool token : {false, true}) {
        const auto res = client.send(verb_of(upper), path, "{}", token);
        EXPECT_TRUE(operation["responses"].contains(std::to_string(res.result_int())))
            << upper << " " << path << " answered " << res.result_int() << " " << res.body();
        if (res.result_int() >= 400) {
          const auto body = nlohmann::json::parse(res.body(), nullptr, false);
          EXPECT_TRUE(body.is_object() && body.contains("error") && body.contains("where"))
              << upper << " " << path << ": " << res.body();
        }
      }
      ++operations;
    }
  }
  EXPECT_EQ(operations, 36);
  // The errors' own headers.
  const auto refused = client.send(http::verb::put, "/api/v1/robot", "{}");
  EXPECT_EQ(refused[http::field::www_authenticate], "Bearer");
  EXPECT_EQ(client.send(http::verb::get, "/api/v1/stream")[http::field::upgrade], "websocket");
}

TEST(HttpServer, LongPollWakesOnPublish) {
  Service service;
  std::thread publisher([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    service.hub.publish({});
  });
  Client client(service.server.port());
  const auto res = client.send(http::verb::get, "/api/v1/navigation?after=0&timeout_ms=5000");
  publisher.join();
  EXPECT_EQ(res.result_int(), 200);
  EXPECT_NE(res.body().find("\"seq\":1"), std::string::npos) << res.body();
  EXPECT_EQ(client.send(http::verb::get, "/api/v1/navigation?after=1&timeout_ms=50").result_int(),
            204);
}

TEST(HttpServer, StreamSendsEveryUpdateInOrderAndSlowReadersSkip) {
  Service service;
  asio::io_context io;
  websocket::stream<tcp::socket> ws(io);
  ws.next_layer().connect(
      tcp::endpoint(asio::ip::make_address("127.0.0.1"), service.server.port()));
  ws.handshake("127.0.0.1", "/api/v1/stream?after=0");
  std::thread publisher([&] {
    for (int k = 0; k < 20; ++k) {
      service.hub.publish({});
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  for (std::uint64_t expected = 1; expected <= 20; ++expected) {
    beast::flat_buffer buffer;
    ws.read(buffer);
    const auto message = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
    EXPECT_EQ(message["topic"], "navigation");
    EXPECT_EQ(message["update"]["seq"], expected);
  }
  publisher.join();
  // A reader far behind starts at the oldest update kept: the gap in seq says what it missed.
  for (std::size_t k = 0; k < NavigationHub::kKept + 10; ++k) service.hub.publish({});
  websocket::stream<tcp::socket> late(io);
  late.next_layer().connect(
      tcp::endpoint(asio::ip::make_address("127.0.0.1"), service.server.port()));
  late.handshake("127.0.0.1", "/api/v1/stream?after=20");
  beast::flat_buffer buffer;
  late.read(buffer);
  const auto first = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
  EXPECT_EQ(first["update"]["seq"], 20 + 10 + 1);
  // A plain GET of the stream is told to upgrade.
  Client client(service.server.port());
  EXPECT_EQ(client.send(http::verb::get, "/api/v1/stream").result_int(), 426);
}

TEST(HttpServer, OversizedAndMalformedRequestsAreRefused) {
  Service service;
  {
    Client client(service.server.port());
    const std::string huge(70 * 1024, 'x');
    EXPECT_EQ(client.send(http::verb::put, "/api/v1/balls", huge, true).result_int(), 413);
  }
  {
    Client client(service.server.port());
    asio::write(client.socket, asio::buffer(std::string("NOT HTTP\r\n\r\n")));
    http::response<http::string_body> res;
    http::read(client.socket, client.buffer, res);
    EXPECT_EQ(res.result_int(), 400);
  }
  // The service is still there.
  Client client(service.server.port());
  EXPECT_EQ(client.send(http::verb::get, "/api/v1/health").result_int(), 200);
}

TEST(HttpServer, TooManyConnectionsGet503AndStopIsPrompt) {
  HttpServerOptions options = Service::with_token();
  options.max_connections = 2;
  auto service = std::make_unique<Service>(options);
  Client a(service->server.port()), b(service->server.port());
  EXPECT_EQ(a.send(http::verb::get, "/api/v1/health").result_int(), 200);
  EXPECT_EQ(b.send(http::verb::get, "/api/v1/health").result_int(), 200);
  Client c(service->server.port());
  http::response<http::string_body> res;
  http::read(c.socket, c.buffer, res);
  EXPECT_EQ(res.result_int(), 503);
  const auto started = std::chrono::steady_clock::now();
  service.reset();  // two idle keep-alive connections open
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 2.0);
}

TEST(HttpServer, AnAddressThatCannotBeBoundIsAnError) {
  HttpServerOptions bad = Service::with_token();
  bad.address = "not-an-address";
  NavigationHub hub;
  ApiContext context{hub, {}, SiteCourt{}, 0.0335};
  EXPECT_THROW({ HttpServer server(bad, api_v1_routes(context)); }, InputError);
}

}  // namespace
}  // namespace ballsight
