#include "ballsight/net/http_robot_link.hpp"

#include <utility>  // before Asio's awaitable.hpp, which uses std::exchange (Boost 1.74)
//
#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/asio/use_future.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <charconv>

#include "ballsight/core/error.hpp"
#include "ballsight/core/json_fields.hpp"
#include "ballsight/service/navigation_hub.hpp"

namespace ballsight {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using asio::awaitable;
using nlohmann::json;
using Response = http::response<http::string_body>;

/// The service answered, but not as a navigation service would (the link does not retry).
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Connects `stream` (closing it from elsewhere cancels the attempt).
awaitable<void> connect(beast::tcp_stream& stream, const RobotLinkOptions& o) {
  tcp::resolver resolver(stream.get_executor());
  const auto endpoints =
      co_await resolver.async_resolve(o.host, std::to_string(o.port), asio::use_awaitable);
  stream.expires_after(o.io_timeout);
  co_await stream.async_connect(endpoints, asio::use_awaitable);
  // Requests go out when written, not after the service's delayed ACK (about 40 ms).
  stream.socket().set_option(tcp::no_delay(true));
}

// Coroutines take their strings by value: a reference could outlive what it refers to.
awaitable<Response> exchange(beast::tcp_stream& stream, const RobotLinkOptions& o, http::verb verb,
                             std::string target, std::string body, std::chrono::milliseconds wait) {
  http::request<http::string_body> req{verb, target, 11};
  req.set(http::field::host, o.host);
  req.keep_alive(true);
  if (!o.token.empty()) req.set(http::field::authorization, "Bearer " + o.token);
  if (!body.empty()) req.set(http::field::content_type, "application/json");
  req.body() = body;
  req.prepare_payload();
  stream.expires_after(o.io_timeout + wait);
  co_await http::async_write(stream, req, asio::use_awaitable);
  beast::flat_buffer buffer;
  Response res;
  co_await http::async_read(stream, buffer, res, asio::use_awaitable);
  co_return res;
}

/// Requests on one keep-alive connection, made again once when it was lost (not after close()).
class HttpClient {
 public:
  explicit HttpClient(const RobotLinkOptions& o) : options_(o) {}

  awaitable<Response> request(http::verb verb, std::string target, std::string body = "",
                              std::chrono::milliseconds wait = std::chrono::milliseconds(0)) {
    for (int attempt = 0;; ++attempt) {
      const bool reused = connected_;
      try {
        if (!stream_) stream_.emplace(co_await asio::this_coro::executor);
        if (!connected_) {
          co_await connect(*stream_, options_);
          connected_ = true;
        }
        Response res = co_await exchange(*stream_, options_, verb, target, body, wait);
        if (!res.keep_alive()) drop();
        co_return res;
      } catch (const boost::system::system_error&) {
        drop();
        // A fresh connection failed (the service is away), or we were closed: no second try.
        if (!reused || attempt > 0 || closed_) throw;
      }
    }
  }
  /// Ends the connection and any request on it, for good.
  void close() {
    closed_ = true;
    if (stream_) stream_->close();
  }

 private:
  void drop() {
    stream_.reset();
    connected_ = false;
  }

  RobotLinkOptions options_;
  std::optional<beast::tcp_stream> stream_;
  bool connected_ = false, closed_ = false;
};

}  // namespace

RobotLinkOptions RobotLinkOptions::from_url(const std::string& url, const std::string& where) {
  std::string rest = url;
  if (rest.rfind("http://", 0) == 0) rest = rest.substr(7);
  while (!rest.empty() && rest.back() == '/') rest.pop_back();
  const std::size_t colon = rest.rfind(':');
  require(colon != std::string::npos && colon > 0, where,
          "expected http://HOST:PORT, got '" + url + "'");
  unsigned port = 0;
  const std::string digits = rest.substr(colon + 1);
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), port);
  require(ec == std::errc() && ptr == digits.data() + digits.size() && port >= 1 && port <= 65535,
          where, "port must be an integer in [1, 65535], got '" + digits + "'");
  RobotLinkOptions o;
  o.host = rest.substr(0, colon);
  o.port = static_cast<unsigned short>(port);
  return o;
}

void RobotLinkOptions::validate() const {
  require(!host.empty(), "host", "must not be empty");
  require(poll_wait.count() >= 0 && poll_wait.count() <= 30000, "poll_wait", "must be 0-30 s");
  require(io_timeout.count() >= 100, "io_timeout", "must be at least 100 ms");
  require(keep >= 1, "keep", "must be at least 1");
  backoff.validate();
}

struct HttpRobotLink::Impl {
  explicit Impl(const RobotLinkOptions& o) : options(o), inbox(o.keep), writer(o) {}

  RobotLinkOptions options;
  asio::io_context io{1};  // the receiver's
  std::thread thread;
  std::atomic<bool> stopping{false};
  std::function<void()> close_receiver;  // on io's thread

  LinkInbox inbox;

  std::mutex write_mutex;
  asio::io_context write_io{1};
  HttpClient writer;

  /// Hands `update` to the robot unless it was delivered already.
  void deliver(const json& update);
  std::string resume_query();
  awaitable<void> receive();
  awaitable<void> receive_stream();
  awaitable<void> receive_polls();
  std::optional<json> call(http::verb verb, const std::string& target, const json& body);
  void connected(const char* transport) {
    inbox.update_status([transport](LinkStatus& status) {
      status.connected = true;
      status.transport = transport;
    });
  }
};

std::string HttpRobotLink::Impl::resume_query() {
  std::string q = "after=" + std::to_string(inbox.last_seq());
  const std::string service_id = inbox.service_id();
  if (!service_id.empty()) q += "&service=" + service_id;
  return q;
}

void HttpRobotLink::Impl::deliver(const json& raw) {
  LinkUpdate u = parse_link_update(raw);
  u.received_ns = utc_now_ns();
  inbox.deliver(std::move(u));
}

awaitable<void> HttpRobotLink::Impl::receive_stream() {
  websocket::stream<beast::tcp_stream> ws(io);
  close_receiver = [&ws] {
    beast::error_code ignored;
    beast::get_lowest_layer(ws).socket().close(ignored);
  };
  co_await connect(beast::get_lowest_layer(ws), options);
  beast::get_lowest_layer(ws).expires_never();
  websocket::stream_base::timeout timeout{};
  timeout.handshake_timeout = options.io_timeout;
  timeout.idle_timeout = options.io_timeout;  // the service pings an idle client
  timeout.keep_alive_pings = false;
  ws.set_option(timeout);
  if (!options.token.empty()) {
    ws.set_option(
        websocket::stream_base::decorator([token = options.token](websocket::request_type& req) {
          req.set(http::field::authorization, "Bearer " + token);
        }));
  }
  websocket::response_type answer;
  beast::error_code ec;
  co_await ws.async_handshake(answer, options.host, "/api/v1/stream?" + resume_query(),
                              asio::redirect_error(asio::use_awaitable, ec));
  // Refused as a thing unknown (a proxy, an older service): long-poll instead. A 503 (too many
  // connections) is worth another try later.
  if (ec == websocket::error::upgrade_declined &&
      (answer.result_int() == 404 || answer.result_int() == 426)) {
    throw Refused("the stream was refused (" + std::to_string(answer.result_int()) + ")");
  }
  if (ec) throw boost::system::system_error(ec);
  connected("websocket");
  beast::flat_buffer buffer;
  while (!stopping) {
    co_await ws.async_read(buffer, asio::use_awaitable);
    const json message = json::parse(beast::buffers_to_string(buffer.data()), nullptr, false);
    buffer.consume(buffer.size());
    if (message.is_object() && message.value("topic", "") == "navigation") {
      deliver(message.at("update"));
    }
  }
}

awaitable<void> HttpRobotLink::Impl::receive_polls() {
  HttpClient client(options);
  close_receiver = [&client] { client.close(); };
  while (!stopping) {
    const Response res =
        co_await client.request(http::verb::get,
                                "/api/v1/navigation?" + resume_query() +
                                    "&timeout_ms=" + std::to_string(options.poll_wait.count()),
                                "", options.poll_wait);
    connected("long-poll");
    if (res.result_int() == 200) {
      deliver(json::parse(res.body()));
    } else if (res.result_int() != 204) {
      throw Refused("long-poll answered " + std::to_string(res.result_int()) + ": " + res.body());
    }
  }
}

awaitable<void> HttpRobotLink::Impl::receive() {
  bool websocket = options.websocket;
  int failures = 0;
  asio::steady_timer pause(io);
  while (!stopping) {
    const std::uint64_t before = inbox.status().delivered;
    std::string error;
    try {
      if (websocket) {
        co_await receive_stream();
      } else {
        co_await receive_polls();
      }
    } catch (const Refused& e) {
      error = e.what();
      if (websocket) websocket = false;  // try long-polling at once
    } catch (const std::exception& e) {
      error = e.what();
    }
    close_receiver = {};
    if (stopping) break;
    inbox.update_status([&](LinkStatus& status) {
      if (status.connected) ++status.reconnects;
      status.connected = false;
      status.last_error = error;
      failures = status.delivered > before ? 1 : failures + 1;
    });
    pause.expires_after(options.backoff.after(failures));
    close_receiver = [&pause] { pause.cancel(); };
    beast::error_code ec;
    co_await pause.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    close_receiver = {};
  }
}

HttpRobotLink::HttpRobotLink(const RobotLinkOptions& options)
    : impl_(std::make_unique<Impl>(options)) {
  options.validate();
  Impl& s = *impl_;
  asio::co_spawn(s.io, s.receive(), asio::detached);
  s.thread = std::thread([&s] { s.io.run(); });
}

HttpRobotLink::~HttpRobotLink() {
  stop();
}

void HttpRobotLink::stop() {
  Impl& s = *impl_;
  if (s.stopping.exchange(true)) return;
  asio::post(s.io, [&s] {
    if (s.close_receiver) s.close_receiver();
  });
  s.thread.join();
  s.inbox.close();
}

std::optional<LinkUpdate> HttpRobotLink::next(std::chrono::milliseconds timeout) {
  return impl_->inbox.take(timeout, false);
}

std::optional<LinkUpdate> HttpRobotLink::latest(std::chrono::milliseconds timeout) {
  return impl_->inbox.take(timeout, true);
}

std::optional<json> HttpRobotLink::Impl::call(http::verb verb, const std::string& target,
                                              const json& body) {
  const std::lock_guard lock(write_mutex);
  std::string error;
  try {
    auto done =
        asio::co_spawn(write_io, writer.request(verb, target, body.dump()), asio::use_future);
    write_io.restart();
    write_io.run();
    const Response res = done.get();
    if (res.result_int() == 200) {
      const json answer = json::parse(res.body(), nullptr, false);
      if (!answer.is_discarded()) return answer;
      error = target + " answered 200 with no JSON";
    } else {
      error = target + " answered " + std::to_string(res.result_int()) + ": " + res.body();
    }
  } catch (const std::exception& e) {
    error = target + ": " + e.what();
  }
  inbox.update_status([&error](LinkStatus& status) { status.last_error = error; });
  return std::nullopt;
}

std::optional<json> HttpRobotLink::call(const std::string& method, const std::string& target,
                                        const json& body) {
  return impl_->call(http::string_to_verb(method), target, body);
}

std::optional<json> HttpRobotLink::drive_simulated(std::uint64_t seq, double speed_mps,
                                                   double turn_rate_dps) {
  return call("PUT", "/api/v1/sim/drive",
              {{"seq", seq}, {"speed_mps", speed_mps}, {"turn_rate_dps", turn_rate_dps}});
}

bool HttpRobotLink::acknowledge(std::uint64_t seq) {
  return impl_->call(http::verb::post, "/api/v1/navigation/ack", {{"seq", seq}}).has_value();
}

bool HttpRobotLink::report_collected(const std::vector<Vec2>& positions, std::optional<int> held) {
  json body = {{"balls", json::array()}};
  for (const Vec2& p : positions) body["balls"].push_back({{"x_m", p.x()}, {"y_m", p.y()}});
  if (held) body["held"] = *held;
  return impl_->call(http::verb::post, "/api/v1/collected", body).has_value();
}

bool HttpRobotLink::report_unreachable(const std::vector<Vec2>& positions,
                                       const std::string& reason) {
  json body = {{"balls", json::array()}, {"reason", reason}};
  for (const Vec2& p : positions) body["balls"].push_back({{"x_m", p.x()}, {"y_m", p.y()}});
  return impl_->call(http::verb::post, "/api/v1/unreachable", body).has_value();
}

bool HttpRobotLink::set_pose(const Pose2D& pose) {
  return impl_->call(http::verb::put, "/api/v1/robot", pose_json(pose)).has_value();
}

LinkStatus HttpRobotLink::status() const {
  return impl_->inbox.status();
}

}  // namespace ballsight
