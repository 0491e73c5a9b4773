// The service under load, through real sockets on 127.0.0.1: 100 WebSocket clients reading 30
// updates a second for 10 s each receive every update in order, while one client that stopped
// reading loses only its own messages (dropped and counted), and the publishing pipeline is never
// held up.
#include <gtest/gtest.h>

#include <utility>  // before Asio's awaitable.hpp (Boost 1.74)
//
#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <thread>

#include "ballsight/net/api.hpp"
#include "ballsight/net/http_server.hpp"
#include "wait_until.hpp"

namespace ballsight {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

/// An update the size of a real one: 30 balls and a route through them.
NavigationUpdate realistic_update(int k) {
  NavigationUpdate u;
  u.capture_time_ns = utc_now_ns();
  for (int b = 0; b < 30; ++b) {
    const Vec2 p(-10.0 + 0.7 * b, 0.1 * ((b * 7 + k) % 50) - 2.5);
    u.world.balls.push_back({p, Eigen::Matrix2d::Identity() * 1e-4, {0, 1}});
    u.route.order.push_back(b);
    u.route.visits_m.push_back(p);
    u.route.waypoints_m.push_back(p);
  }
  return u;
}

struct Received {
  std::vector<std::uint64_t> seqs;
  bool failed = false;
};

asio::awaitable<void> read_stream(unsigned short port, Received& out, std::uint64_t last) {
  try {
    auto executor = co_await asio::this_coro::executor;
    websocket::stream<beast::tcp_stream> ws(executor);
    co_await beast::get_lowest_layer(ws).async_connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), port), asio::use_awaitable);
    co_await ws.async_handshake("127.0.0.1", "/api/v1/stream", asio::use_awaitable);
    // Every read has a deadline: a reader that hears nothing for 30 s fails.
    websocket::stream_base::timeout deadline{};
    deadline.handshake_timeout = std::chrono::seconds(30);
    deadline.idle_timeout = std::chrono::seconds(30);
    deadline.keep_alive_pings = false;
    beast::get_lowest_layer(ws).expires_never();
    ws.set_option(deadline);
    beast::flat_buffer buffer;
    while (out.seqs.empty() || out.seqs.back() < last) {
      co_await ws.async_read(buffer, asio::use_awaitable);
      const auto m = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
      buffer.consume(buffer.size());
      out.seqs.push_back(m["update"]["seq"].get<std::uint64_t>());
    }
    co_await ws.async_close(websocket::close_code::normal, asio::use_awaitable);
  } catch (const std::exception&) {
    out.failed = true;
  }
}

TEST(ServiceLoad, HundredClientsAtThirtyHertzGetEveryUpdateAndAStalledOneHoldsUpNobody) {
  constexpr int kClients = 100, kUpdates = 300;
  constexpr double kRateHz = 30.0;
  NavigationHub hub;
  ApiContext context{hub, {"ne", "se", "sw", "nw"}, SiteCourt{}, 0.0335};
  HttpServerOptions options;
  options.port = 0;
  options.token = "0123456789abcdef0123";
  HttpServer server(options, api_v1_routes(context));

  // The stalled client: a WebSocket that never reads, with a small receive buffer.
  asio::io_context stalled_io;
  websocket::stream<tcp::socket> stalled(stalled_io);
  stalled.next_layer().open(tcp::v4());
  stalled.next_layer().set_option(asio::socket_base::receive_buffer_size(4096));
  stalled.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server.port()));
  stalled.handshake("127.0.0.1", "/api/v1/stream");

  asio::io_context io;
  std::vector<Received> received(kClients);
  for (Received& r : received) {
    asio::co_spawn(io, read_stream(server.port(), r, kUpdates), asio::detached);
  }
  std::thread clients([&] { io.run(); });
  const bool all_connected =
      test::wait_until([&] { return server.clients().size() >= kClients + 1; });
  if (!all_connected) {  // the readers end; the assertion below says why
    io.stop();
    clients.join();
  }
  ASSERT_TRUE(all_connected) << server.clients().size() << " of " << kClients + 1
                             << " clients connected";

  // The pipeline: 30 updates a second, each publish timed.
  const auto start = Clock::now();
  double longest_publish_ms = 0.0;
  for (int k = 0; k < kUpdates; ++k) {
    NavigationUpdate u = realistic_update(k);
    const auto before = Clock::now();
    hub.publish(std::move(u));
    longest_publish_ms =
        std::max(longest_publish_ms,
                 std::chrono::duration<double, std::milli>(Clock::now() - before).count());
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>((k + 1) / kRateHz)));
  }
  const double publishing_s = std::chrono::duration<double>(Clock::now() - start).count();
  clients.join();  // every reader ends at the last update (or fails)

  for (int c = 0; c < kClients; ++c) {
    EXPECT_FALSE(received[c].failed) << "client " << c;
    ASSERT_EQ(received[c].seqs.size(), std::size_t{kUpdates}) << "client " << c;
    for (int k = 0; k < kUpdates; ++k) ASSERT_EQ(received[c].seqs[k], k + 1u) << "client " << c;
  }
  // The readers have left (the server hears of their closes on its own thread, later under
  // load); the stalled client is still there, its oldest messages dropped.
  std::vector<ClientStats> left = server.clients();
  for (int k = 0; k < 200 && left.size() > 1; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    left = server.clients();
  }
  ASSERT_EQ(left.size(), 1u);
  EXPECT_GT(left[0].dropped, 0u);
  EXPECT_EQ(left[0].queued, options.client_queue);
  // Publishing never waited for a client: the pipeline kept its rate.
  EXPECT_LT(publishing_s, kUpdates / kRateHz + 1.0);
  EXPECT_LT(longest_publish_ms, 50.0);
}

}  // namespace
}  // namespace ballsight
