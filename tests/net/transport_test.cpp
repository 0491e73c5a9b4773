// The transport names no API: a module of the test's own (not API v1) registers a route that
// long-polls, a WebSocket channel and where its publications come from, and the server carries
// them all.
#include <gtest/gtest.h>

#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <future>

#include "ballsight/net/api_request.hpp"
#include "ballsight/net/http_server.hpp"
#include "http_request.hpp"
#include "wait_until.hpp"

namespace ballsight {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
using namespace std::chrono_literals;

// Says hello, echoes what it is sent, and tells of every publication.
class EchoChannel : public WebSocketChannel {
 public:
  std::string kind() const override { return "echo"; }
  ClientMessages greeting() override { return {text("hello")}; }
  ClientMessages on_text(const std::string& message) override { return {text("echo " + message)}; }
  ClientMessages on_publish(SharedMessages& shared) override {
    return {{shared.get<std::shared_ptr<const std::string>>(
                 "news", [] { return std::make_shared<const std::string>("published"); }),
             false}};
  }
  ClientMessages on_tick(SharedMessages&) override { return {}; }

 private:
  static ClientMessage text(std::string s) {
    return {std::make_shared<const std::string>(std::move(s)), false};
  }
};

struct EchoModule {
  std::atomic<int> published{0};
  std::atomic<int> asked{0};       // requests its route answered
  std::function<void()> listener;  // the server's, while it listens
  int unlistened = 0;

  std::optional<ApiResponse> news() const {
    if (published == 0) return std::nullopt;
    return ApiResponse{200, R"({"published": )" + std::to_string(published) + "}"};
  }
  ApiRoutes routes() {
    ApiRoutes r;
    r.add({.prefix = "/echo/", .handler = [this](const ApiRequest&) {
             ++asked;
             if (std::optional<ApiResponse> now = news()) return *now;
             ApiResponse pending{204, ""};
             pending.retry = [this] { return news(); };
             pending.wait = 10s;
             return pending;
           }});
    r.add_websocket(
        [](const ApiRequest& request,
           const std::string&) -> std::optional<std::variant<WebSocketOpened, ApiResponse>> {
          const std::string path = split_target(request.target).path;
          if (path == "/echo/closed") return api_error(403, "closed today", path);
          if (path != "/echo/ws") return std::nullopt;
          return WebSocketOpened{std::make_unique<EchoChannel>(), ""};
        });
    r.set_events({[this](std::function<void()> f) {
                    listener = std::move(f);
                    return 7;
                  },
                  [this](int id) {
                    EXPECT_EQ(id, 7);
                    ++unlistened;
                  }});
    return r;
  }
  void publish() {
    ++published;
    listener();
  }
};

std::string read_text(beast::websocket::stream<asio::ip::tcp::socket>& ws) {
  beast::flat_buffer buffer;
  ws.read(buffer);
  return beast::buffers_to_string(buffer.data());
}

TEST(HttpServer, CarriesAModuleOfItsOwnRoutesChannelsAndPublications) {
  EchoModule module;
  HttpServerOptions options;
  options.port = 0;
  options.token = "0123456789abcdef0123";
  HttpServer server(options, module.routes());
  ASSERT_TRUE(module.listener) << "the server did not listen for publications";

  asio::io_context io;
  beast::websocket::stream<asio::ip::tcp::socket> ws(io);
  ws.next_layer().connect({asio::ip::make_address("127.0.0.1"), server.port()});
  ws.handshake("127.0.0.1", "/echo/ws");
  EXPECT_EQ(read_text(ws), "hello");
  ws.write(asio::buffer(std::string("ball")));
  EXPECT_EQ(read_text(ws), "echo ball");
  ASSERT_EQ(server.clients().size(), 1u);
  EXPECT_EQ(server.clients()[0].kind, "echo");

  // A long-poll parked until the module publishes, then answered by its retry.
  auto poll = std::async(std::launch::async, [&] {
    return test::request(server.port(), beast::http::verb::get, "/echo/news");
  });
  ASSERT_TRUE(test::wait_until([&] { return module.asked == 1; }, 10s)) << "the poll never came";
  // Parked now: the route answered 204 with a retry, and the I/O thread parks it before it
  // handles the publication below (both happen on it, in turn).
  EXPECT_EQ(poll.wait_for(200ms), std::future_status::timeout) << "answered before the news";
  module.publish();
  ASSERT_EQ(poll.wait_for(10s), std::future_status::ready) << "the parked poll was not woken";
  const test::Reply reply = poll.get();
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.body["published"], 1);
  EXPECT_EQ(read_text(ws), "published");

  // An upgrade no module takes, and one its module refuses.
  const auto upgrade_status = [&](const std::string& target) {
    asio::ip::tcp::socket other(io);
    other.connect({asio::ip::make_address("127.0.0.1"), server.port()});
    beast::http::request<beast::http::empty_body> upgrade{beast::http::verb::get, target, 11};
    upgrade.set(beast::http::field::host, "127.0.0.1");
    upgrade.set(beast::http::field::connection, "Upgrade");
    upgrade.set(beast::http::field::upgrade, "websocket");
    upgrade.set(beast::http::field::sec_websocket_key, "dGhlIHNhbXBsZSBub25jZQ==");
    upgrade.set(beast::http::field::sec_websocket_version, "13");
    beast::http::write(other, upgrade);
    beast::flat_buffer buffer;
    beast::http::response<beast::http::string_body> answer;
    beast::http::read(other, buffer, answer);
    return answer.result_int();
  };
  EXPECT_EQ(upgrade_status("/elsewhere"), 404);
  EXPECT_EQ(upgrade_status("/echo/closed"), 403);

  server.stop();
  EXPECT_EQ(module.unlistened, 1);
}

}  // namespace
}  // namespace ballsight
