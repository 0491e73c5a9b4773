#include "ballsight/net/http_server.hpp"

#include <utility>  // before Asio's awaitable.hpp, which uses std::exchange (Boost 1.74)
//
#include <atomic>
#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/net/api_request.hpp"
#include "ballsight/net/bearer_token.hpp"
#include "ballsight/net/web_files.hpp"

namespace ballsight {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using asio::awaitable;
using Request = http::request<http::string_body>;
using WebSocket = websocket::stream<beast::tcp_stream>;

http::response<http::string_body> http_answer(const ApiResponse& response, unsigned version,
                                              bool keep_alive) {
  http::response<http::string_body> res{static_cast<http::status>(response.status), version};
  res.set(http::field::server, "ballsight");
  if (!response.body.empty()) res.set(http::field::content_type, response.content_type);
  if (response.status == 401) res.set(http::field::www_authenticate, "Bearer");
  if (response.status == 426) res.set(http::field::upgrade, "websocket");
  res.keep_alive(keep_alive);
  res.body() = response.body;
  res.prepare_payload();
  return res;
}

/// Ends a connection's coroutine: a failure inside it (a bug, since nothing a client sends may
/// throw) closes that connection only, and is said on stderr; it must not end the service.
void end_of_connection(const std::exception_ptr& failure) {
  if (!failure) return;
  try {
    std::rethrow_exception(failure);
  } catch (const std::exception& e) {
    std::cerr << "ballsight serve: a connection failed: " << e.what() << "\n";
  } catch (...) {
    std::cerr << "ballsight serve: a connection failed\n";
  }
}

/// Runs `work`, saying on stderr what `what` was when it fails (the I/O thread goes on).
template <class Work>
void guarded(const char* what, Work&& work) {
  try {
    work();
  } catch (const std::exception& e) {
    std::cerr << "ballsight serve: " << what << " failed: " << e.what() << "\n";
  }
}

/// A WebSocket client: its socket, its channel (what an API module says to it), and the messages
/// waiting for it. Touched on the I/O thread only, but for the counters `clients()` reads.
struct Peer {
  Peer(WebSocket socket, std::uint64_t id_, std::unique_ptr<WebSocketChannel> channel_,
       std::string remote_, std::size_t limit_)
      : ws(std::move(socket)),
        wake(ws.get_executor()),
        id(id_),
        channel(std::move(channel_)),
        kind(channel->kind()),
        remote(std::move(remote_)),
        limit(limit_) {}

  void push(ClientMessages messages) {
    for (ClientMessage& m : messages) push(std::move(m));
  }
  void push(ClientMessage message) {
    if (queue.size() >= limit) {
      queue.pop_front();
      ++dropped;
    }
    queue.push_back(std::move(message));
    queued = queue.size();
    wake.cancel();
  }

  WebSocket ws;
  asio::steady_timer wake;  // cancelled when a message is queued or the client leaves
  const std::uint64_t id;
  const std::unique_ptr<WebSocketChannel> channel;
  const std::string kind;
  const std::string remote;
  const std::size_t limit;
  std::deque<ClientMessage> queue;
  bool closed = false;
  std::atomic<std::uint64_t> sent{0}, dropped{0};
  std::atomic<std::size_t> queued{0};
};

}  // namespace

void HttpServerOptions::validate() const {
  require(body_limit >= 1024 && body_limit <= (16u << 20), "body_limit", "must be 1 KiB-16 MiB");
  require(header_limit >= 1024 && header_limit <= (1u << 20), "header_limit",
          "must be 1 KiB-1 MiB");
  require(max_connections >= 1 && max_connections <= 10000, "max_connections",
          "must be in [1, 10000]");
  require(idle_timeout.count() >= 1, "idle_timeout", "must be at least 1 s");
  require(client_queue >= 1 && client_queue <= 100000, "client_queue", "must be in [1, 100000]");
  require(client_send_buffer >= 4096, "client_send_buffer", "must be at least 4 KiB");
  require(!token.empty(), "token", "must not be empty");
}

struct HttpServer::Impl {
  Impl(const HttpServerOptions& o, ApiRoutes r) : options(o), routes(std::move(r)) {
    if (!o.web_root.empty()) pages.emplace(o.web_root, o.node_modules);
  }

  HttpServerOptions options;
  const ApiRoutes routes;
  std::optional<WebFiles> pages;
  asio::io_context io{1};
  asio::executor_work_guard<asio::io_context::executor_type> work{io.get_executor()};
  asio::thread_pool workers{2};  // requests whose route runs long, off the I/O thread
  tcp::acceptor acceptor{io};
  asio::steady_timer health_timer{io};
  std::thread thread;
  std::atomic<bool> stopping{false};
  int listener = 0;

  // I/O thread only:
  std::uint64_t next_id = 1;
  std::map<std::uint64_t, std::function<void()>> closers;  // every open connection
  std::set<asio::steady_timer*> parked;                    // waiting long-polls
  // Also read by clients():
  mutable std::mutex peers_mutex;
  std::map<std::uint64_t, std::shared_ptr<Peer>> peers;
  std::atomic<int> open{0};

  awaitable<void> accept_loop();
  awaitable<void> session(tcp::socket socket, std::uint64_t id);
  awaitable<ApiResponse> long_poll(ApiResponse pending);
  awaitable<void> serve_websocket(beast::tcp_stream stream, Request req, std::uint64_t id,
                                  std::string remote, WebSocketOpened opened);
  awaitable<void> write_loop(std::shared_ptr<Peer> peer);
  awaitable<void> health_loop();
  void broadcast();
  std::vector<std::shared_ptr<Peer>> open_peers() const;
  void close_all();
};

awaitable<void> HttpServer::Impl::accept_loop() {
  while (!stopping) {
    beast::error_code ec;
    tcp::socket socket =
        co_await acceptor.async_accept(asio::redirect_error(asio::use_awaitable, ec));
    if (ec) {
      if (stopping || ec == asio::error::operation_aborted) co_return;
      // Out of file descriptors, say: wait a little instead of spinning.
      asio::steady_timer pause(io, std::chrono::milliseconds(100));
      co_await pause.async_wait(asio::redirect_error(asio::use_awaitable, ec));
      continue;
    }
    const std::uint64_t id = next_id++;
    asio::co_spawn(io, session(std::move(socket), id), end_of_connection);
  }
}

awaitable<ApiResponse> HttpServer::Impl::long_poll(ApiResponse pending) {
  const auto deadline = std::chrono::steady_clock::now() + pending.wait;
  const auto retry = std::move(pending.retry);
  asio::steady_timer timer(io);
  parked.insert(&timer);
  // Unparked however this ends (a module's retry may throw): broadcast() must never see it gone.
  const std::unique_ptr<asio::steady_timer, std::function<void(asio::steady_timer*)>> unpark(
      &timer, [this](asio::steady_timer* t) { parked.erase(t); });
  ApiResponse answer = std::move(pending);
  while (!stopping) {
    if (std::optional<ApiResponse> a = retry()) {
      answer = std::move(*a);
      break;
    }
    if (std::chrono::steady_clock::now() >= deadline) break;
    timer.expires_at(deadline);  // broadcast() cancels it when an update comes
    beast::error_code ec;
    co_await timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
  }
  co_return answer;
}

awaitable<void> HttpServer::Impl::session(tcp::socket socket, std::uint64_t id) {
  beast::error_code ec;
  const tcp::endpoint remote_endpoint = socket.remote_endpoint(ec);
  const bool local = !ec && remote_endpoint.address().is_loopback();
  const std::string remote =
      ec ? "?"
         : remote_endpoint.address().to_string() + ":" + std::to_string(remote_endpoint.port());
  // Each message goes out when written: with Nagle's algorithm a small WebSocket frame after
  // another waited for the client's delayed ACK, about 40 ms (the chain's p99 outliers).
  beast::error_code no_delay;  // a socket that refuses it still works, only slower
  socket.set_option(tcp::no_delay(true), no_delay);
  beast::tcp_stream stream(std::move(socket));
  const int open_now = ++open;
  closers[id] = [&stream] {
    beast::error_code ignored;
    stream.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream.socket().close(ignored);
  };
  struct Leave {  // however the session ends
    Impl& s;
    std::uint64_t id;
    ~Leave() {
      s.closers.erase(id);
      --s.open;
    }
  } leave{*this, id};
  beast::flat_buffer buffer;
  if (open_now > options.max_connections) {
    stream.expires_after(options.idle_timeout);
    co_await http::async_write(
        stream, http_answer(api_error(503, "too many connections", "server"), 11, false),
        asio::redirect_error(asio::use_awaitable, ec));
    co_return;
  }
  while (!stopping) {
    http::request_parser<http::string_body> parser;
    parser.body_limit(options.body_limit);
    parser.header_limit(static_cast<std::uint32_t>(options.header_limit));
    stream.expires_after(options.idle_timeout);
    co_await http::async_read(stream, buffer, parser,
                              asio::redirect_error(asio::use_awaitable, ec));
    const bool malformed = ec && ec != http::error::end_of_stream &&
                           ec.category() == make_error_code(http::error::end_of_stream).category();
    if (malformed) {
      const int status = ec == http::error::body_limit     ? 413
                         : ec == http::error::header_limit ? 431
                                                           : 400;
      stream.expires_after(options.idle_timeout);
      co_await http::async_write(stream,
                                 http_answer(api_error(status, ec.message(), "request"), 11, false),
                                 asio::redirect_error(asio::use_awaitable, ec));
      co_return;
    }
    if (ec || stopping) co_return;
    Request req = parser.release();
    ApiRequest request;
    request.method = std::string(req.method_string());
    request.target = std::string(req.target());
    request.body = req.body();
    const auto auth = req.find(http::field::authorization);
    request.authorized =
        auth != req.end() &&
        shows_token(std::string_view(auth->value().data(), auth->value().size()), options.token);
    ApiResponse response;
    if (!local && !options.open_reads && !request.authorized) {
      response = api_error(401, "requests from other hosts need the token", "headers");
    } else if (websocket::is_upgrade(req)) {
      auto opened =
          routes.open_websocket(request, std::string(req[http::field::sec_websocket_protocol]));
      if (auto* channel = std::get_if<WebSocketOpened>(&opened)) {
        co_await serve_websocket(std::move(stream), std::move(req), id, remote,
                                 std::move(*channel));
        co_return;
      }
      response = std::move(std::get<ApiResponse>(opened));
    } else if (const std::string path = split_target(request.target).path;
               pages && request.method == "GET" && WebFiles::is_page_path(path)) {
      response = pages->get(path);
    } else if (routes.runs_long(request.target)) {
      response = co_await asio::co_spawn(
          workers, [&]() -> awaitable<ApiResponse> { co_return routes.answer(request); },
          asio::use_awaitable);
    } else {
      response = routes.answer(request);
      if (response.retry) response = co_await long_poll(std::move(response));
    }
    stream.expires_after(options.idle_timeout);
    co_await http::async_write(stream, http_answer(response, req.version(), req.keep_alive()),
                               asio::redirect_error(asio::use_awaitable, ec));
    if (ec || !req.keep_alive()) break;
  }
  stream.socket().shutdown(tcp::socket::shutdown_send, ec);
}

awaitable<void> HttpServer::Impl::serve_websocket(beast::tcp_stream stream, Request req,
                                                  std::uint64_t id, std::string remote,
                                                  WebSocketOpened opened) {
  stream.expires_never();  // the WebSocket's own timeout takes over
  beast::error_code ec;
  stream.socket().set_option(asio::socket_base::send_buffer_size(options.client_send_buffer), ec);
  auto peer = std::make_shared<Peer>(WebSocket(std::move(stream)), id, std::move(opened.channel),
                                     remote, options.client_queue);
  WebSocket& ws = peer->ws;
  closers[id] = [peer] {
    beast::error_code ignored;
    peer->closed = true;
    peer->wake.cancel();
    beast::get_lowest_layer(peer->ws).socket().close(ignored);
  };
  websocket::stream_base::timeout timeout{};
  timeout.handshake_timeout = options.idle_timeout;
  timeout.idle_timeout = options.idle_timeout;  // a client that answers no ping is let go
  timeout.keep_alive_pings = true;
  ws.set_option(timeout);
  ws.read_message_max(options.body_limit);
  if (!opened.subprotocol.empty()) {
    ws.set_option(websocket::stream_base::decorator(
        [subprotocol = opened.subprotocol](websocket::response_type& res) {
          res.set(http::field::sec_websocket_protocol, subprotocol);
        }));
  }
  co_await ws.async_accept(req, asio::redirect_error(asio::use_awaitable, ec));
  if (ec) co_return;
  peer->push(peer->channel->greeting());
  {
    const std::lock_guard lock(peers_mutex);
    peers[id] = peer;
  }
  asio::co_spawn(io, write_loop(peer), end_of_connection);
  beast::flat_buffer buffer;
  while (!peer->closed) {
    co_await ws.async_read(buffer, asio::redirect_error(asio::use_awaitable, ec));
    if (ec) break;
    if (ws.got_text()) peer->push(peer->channel->on_text(beast::buffers_to_string(buffer.data())));
    buffer.consume(buffer.size());
  }
  peer->closed = true;
  peer->wake.cancel();
  const std::lock_guard lock(peers_mutex);
  peers.erase(id);
}

awaitable<void> HttpServer::Impl::write_loop(std::shared_ptr<Peer> peer) {
  beast::error_code ec;
  while (!peer->closed) {
    if (peer->queue.empty()) {
      peer->wake.expires_at(asio::steady_timer::time_point::max());
      co_await peer->wake.async_wait(asio::redirect_error(asio::use_awaitable, ec));
      continue;
    }
    const ClientMessage message = std::move(peer->queue.front());
    peer->queue.pop_front();
    peer->queued = peer->queue.size();
    peer->ws.binary(message.binary);
    co_await peer->ws.async_write(asio::buffer(*message.data),
                                  asio::redirect_error(asio::use_awaitable, ec));
    if (ec) break;
    ++peer->sent;
  }
  if (!peer->closed) {  // the client is gone: end its reader too
    peer->closed = true;
    beast::get_lowest_layer(peer->ws).socket().close(ec);
  }
}

awaitable<void> HttpServer::Impl::health_loop() {
  while (!stopping) {
    health_timer.expires_after(std::chrono::seconds(1));
    beast::error_code ec;
    co_await health_timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    if (stopping) co_return;
    SharedMessages shared;
    for (const auto& peer : open_peers())
      guarded("a client's tick", [&] { peer->push(peer->channel->on_tick(shared)); });
  }
}

std::vector<std::shared_ptr<Peer>> HttpServer::Impl::open_peers() const {
  std::vector<std::shared_ptr<Peer>> list;
  const std::lock_guard lock(peers_mutex);
  for (const auto& [id, peer] : peers)
    if (!peer->closed) list.push_back(peer);
  return list;
}

void HttpServer::Impl::broadcast() {
  SharedMessages shared;  // an update's messages are made once, for every client that gets them
  for (const auto& peer : open_peers())
    guarded("a client's update", [&] { peer->push(peer->channel->on_publish(shared)); });
  for (asio::steady_timer* timer : parked) timer->cancel();
}

void HttpServer::Impl::close_all() {
  beast::error_code ec;
  acceptor.close(ec);
  health_timer.cancel();
  for (asio::steady_timer* timer : parked) timer->cancel();
  const auto closing = closers;  // a closer may end its session, which erases it
  for (const auto& [id, close] : closing) close();
}

HttpServer::HttpServer(const HttpServerOptions& options, ApiRoutes routes)
    : impl_(std::make_unique<Impl>(options, std::move(routes))) {
  options.validate();
  beast::error_code ec;
  const auto address = asio::ip::make_address(options.address, ec);
  require(!ec, "--listen", "'" + options.address + "' is not an IP address");
  const tcp::endpoint endpoint(address, options.port);
  tcp::acceptor& acceptor = impl_->acceptor;
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
  require(!ec, "--listen",
          "cannot listen on " + options.address + ":" + std::to_string(options.port) + ": " +
              ec.message());
  Impl& s = *impl_;
  if (const PublishEvents& events = s.routes.events(); events.listen)
    s.listener = events.listen([&s] { asio::post(s.io, [&s] { s.broadcast(); }); });
  asio::co_spawn(s.io, s.accept_loop(), asio::detached);
  asio::co_spawn(s.io, s.health_loop(), asio::detached);
  s.thread = std::thread([&s] { s.io.run(); });
}

HttpServer::~HttpServer() {
  stop();
}

unsigned short HttpServer::port() const {
  return impl_->acceptor.local_endpoint().port();
}

int HttpServer::connections() const {
  return impl_->open;
}

std::vector<ClientStats> HttpServer::clients() const {
  const std::lock_guard lock(impl_->peers_mutex);
  std::vector<ClientStats> out;
  for (const auto& [id, p] : impl_->peers) {
    out.push_back({p->id, p->kind, p->remote, p->sent, p->dropped, p->queued});
  }
  return out;
}

nlohmann::json clients_json(const std::vector<ClientStats>& clients) {
  nlohmann::json out = nlohmann::json::array();
  for (const ClientStats& c : clients) {
    out.push_back({{"id", c.id},
                   {"kind", c.kind},
                   {"remote", c.remote},
                   {"sent", c.sent},
                   {"dropped", c.dropped},
                   {"queued", c.queued}});
  }
  return out;
}

void HttpServer::stop() {
  Impl& s = *impl_;
  if (s.stopping.exchange(true)) return;
  if (const PublishEvents& events = s.routes.events(); events.unlisten) events.unlisten(s.listener);
  asio::post(s.io, [&s] { s.close_all(); });
  s.work.reset();
  s.thread.join();
}

}  // namespace ballsight
