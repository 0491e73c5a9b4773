#include "ballsight/net/http_server.hpp"

#include <sys/socket.h>
#include <sys/stat.h>

#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <fstream>
#include <list>
#include <mutex>
#include <random>
#include <thread>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

/// Equal strings, compared in time that does not depend on where they differ.
bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

http::response<http::string_body> json_response(int status, std::string body, unsigned version,
                                                bool keep_alive) {
  http::response<http::string_body> res{static_cast<http::status>(status), version};
  res.set(http::field::server, "ballsight");
  if (!body.empty()) res.set(http::field::content_type, "application/json");
  res.keep_alive(keep_alive);
  res.body() = std::move(body);
  res.prepare_payload();
  return res;
}

std::string error_body(const std::string& what, const std::string& where) {
  return nlohmann::json{{"error", what}, {"where", where}}.dump();
}

}  // namespace

void HttpServerOptions::validate() const {
  require(body_limit >= 1024 && body_limit <= (16u << 20), "body_limit", "must be 1 KiB-16 MiB");
  require(header_limit >= 1024 && header_limit <= (1u << 20), "header_limit",
          "must be 1 KiB-1 MiB");
  require(max_connections >= 1 && max_connections <= 10000, "max_connections",
          "must be in [1, 10000]");
  require(idle_timeout.count() >= 1, "idle_timeout", "must be at least 1 s");
  require(!token.empty(), "token", "must not be empty");
}

struct HttpServer::Impl {
  HttpServerOptions options;
  Handler handler;
  StreamHandler stream;
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::thread accept_thread;
  std::mutex mutex;
  struct Connection {
    std::shared_ptr<tcp::socket> socket;
    std::thread thread;
    bool done = false;
  };
  std::list<Connection> connections;
  std::atomic<int> open{0};
  std::atomic<bool> stopping{false};

  void accept_loop();
  void serve(tcp::socket& socket);
  void serve_stream(tcp::socket& socket, const http::request<http::string_body>& req,
                    const ApiRequest& request);
  void reap();
};

void HttpServer::Impl::reap() {
  // Joins the threads of connections that have ended (called with the mutex held).
  for (auto it = connections.begin(); it != connections.end();) {
    if (it->done) {
      it->thread.join();
      it = connections.erase(it);
    } else {
      ++it;
    }
  }
}

void HttpServer::Impl::accept_loop() {
  while (!stopping) {
    auto socket = std::make_shared<tcp::socket>(io);
    beast::error_code ec;
    acceptor.accept(*socket, ec);
    if (ec) {
      if (stopping) return;
      continue;
    }
    const std::lock_guard lock(mutex);
    reap();
    if (open >= options.max_connections) {
      http::write(*socket,
                  json_response(503, error_body("too many connections", "server"), 11, false), ec);
      socket->shutdown(tcp::socket::shutdown_both, ec);
      continue;
    }
    ++open;
    connections.push_back({socket, {}, false});
    Connection& c = connections.back();
    c.thread = std::thread([this, &c] {
      serve(*c.socket);
      beast::error_code ignored;
      c.socket->shutdown(tcp::socket::shutdown_both, ignored);
      c.socket->close(ignored);
      const std::lock_guard done_lock(mutex);
      c.done = true;
      --open;
    });
  }
}

void HttpServer::Impl::serve_stream(tcp::socket& socket,
                                    const http::request<http::string_body>& req,
                                    const ApiRequest& request) {
  websocket::stream<tcp::socket&> ws(socket);
  beast::error_code ec;
  ws.accept(req, ec);
  if (ec) return;
  ws.text(true);
  stream(
      request,
      [&](const std::string& message) {
        ws.write(asio::buffer(message), ec);
        return !ec;
      },
      stopping);
  ws.close(websocket::close_code::going_away, ec);
}

void HttpServer::Impl::serve(tcp::socket& socket) {
  // Reads and writes block at most the idle timeout (a silent or stuck client is let go).
  const timeval tv{static_cast<time_t>(options.idle_timeout.count()), 0};
  ::setsockopt(socket.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  ::setsockopt(socket.native_handle(), SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
  beast::error_code ec;
  const tcp::endpoint remote = socket.remote_endpoint(ec);
  const bool local = !ec && remote.address().is_loopback();
  beast::flat_buffer buffer;
  while (!stopping) {
    http::request_parser<http::string_body> parser;
    parser.body_limit(options.body_limit);
    parser.header_limit(static_cast<std::uint32_t>(options.header_limit));
    http::read(socket, buffer, parser, ec);
    if (ec == http::error::end_of_stream || ec == asio::error::eof ||
        ec == asio::error::connection_reset || ec == asio::error::would_block ||
        ec == asio::error::try_again || ec == asio::error::timed_out || stopping) {
      return;
    }
    if (ec) {
      const int status = ec == http::error::body_limit     ? 413
                         : ec == http::error::header_limit ? 431
                                                           : 400;
      http::write(socket, json_response(status, error_body(ec.message(), "request"), 11, false),
                  ec);
      return;
    }
    const auto& req = parser.get();
    ApiRequest request;
    request.method = std::string(req.method_string());
    request.target = std::string(req.target());
    request.body = req.body();
    const auto auth = req.find(http::field::authorization);
    request.authorized =
        auth != req.end() && same_secret(std::string(auth->value()), "Bearer " + options.token);
    ApiResponse response;
    if (!local && !options.open_reads && !request.authorized) {
      response = {401, error_body("requests from other hosts need the token", "headers")};
    } else if (websocket::is_upgrade(req)) {
      if (!stream || !is_stream_target(request.target)) {
        response = {404, error_body("no WebSocket here", request.target)};
      } else if (const std::optional<ApiResponse> refusal = stream_refusal(request)) {
        response = *refusal;
      } else {
        serve_stream(socket, req, request);
        return;
      }
    } else {
      response = handler(request);
    }
    http::write(
        socket,
        json_response(response.status, std::move(response.body), req.version(), req.keep_alive()),
        ec);
    if (ec || !req.keep_alive()) return;
  }
}

HttpServer::HttpServer(const HttpServerOptions& options, Handler handler, StreamHandler stream)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  impl_->options = options;
  impl_->handler = std::move(handler);
  impl_->stream = std::move(stream);
  beast::error_code ec;
  const auto address = asio::ip::make_address(options.address, ec);
  require(!ec, "--listen", "'" + options.address + "' is not an IP address");
  const tcp::endpoint endpoint(address, options.port);
  impl_->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl_->acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) impl_->acceptor.bind(endpoint, ec);
  if (!ec) impl_->acceptor.listen(asio::socket_base::max_listen_connections, ec);
  require(!ec, "--listen",
          "cannot listen on " + options.address + ":" + std::to_string(options.port) + ": " +
              ec.message());
  impl_->accept_thread = std::thread([this] { impl_->accept_loop(); });
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

void HttpServer::stop() {
  if (impl_->stopping.exchange(true)) return;
  beast::error_code ec;
  // Closing the acceptor does not wake a blocking accept on Linux; shutting it down does.
  ::shutdown(impl_->acceptor.native_handle(), SHUT_RDWR);
  impl_->acceptor.close(ec);
  if (impl_->accept_thread.joinable()) impl_->accept_thread.join();
  std::list<Impl::Connection> connections;
  {
    const std::lock_guard lock(impl_->mutex);
    for (Impl::Connection& c : impl_->connections)
      c.socket->shutdown(tcp::socket::shutdown_both, ec);
    connections.splice(connections.end(), impl_->connections);
  }
  for (Impl::Connection& c : connections) c.thread.join();
}

std::string read_or_create_token(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  if (fs::exists(file)) {
    std::string text = read_file(file);
    text = text.substr(0, text.find_first_of("\r\n"));
    require(text.size() >= 16, file.string(), "the token must be at least 16 characters");
    return text;
  }
  std::random_device random;
  std::string token;
  constexpr char kHex[] = "0123456789abcdef";
  for (int i = 0; i < 32; ++i) token += kHex[random() % 16];
  write_file_atomic(file, token + "\n");
  require(::chmod(file.c_str(), 0600) == 0, file.string(), "cannot make it private (0600)");
  return token;
}

}  // namespace ballsight
