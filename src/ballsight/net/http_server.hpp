#pragma once
// The navigation service's HTTP/1.1 server (Boost.Beast, kept inside http_server.cpp: it compiles
// slowly). One thread accepts; each connection is served by a thread of its own, at most
// `max_connections` at once (a long-poll waits in its connection's thread, so it never holds up
// another client, and a WebSocket client of the stream is sent every update from its own thread,
// so a slow one holds up nobody). Requests are bounded (body, header, idle time); the bearer token
// decides whether a request may write, and whether a client on another host may read.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "ballsight/net/api.hpp"

namespace ballsight {

struct HttpServerOptions {
  std::string address = "127.0.0.1";
  unsigned short port = 8080;  // 0: a free port (HttpServer::port() says which)
  std::string token;           // writes need "Authorization: Bearer <token>"
  bool open_reads = false;     // reads from other hosts need no token
  std::size_t body_limit = 64 * 1024;
  std::size_t header_limit = 8 * 1024;
  int max_connections = 64;
  std::chrono::seconds idle_timeout{30};

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

class HttpServer {
 public:
  using Handler = std::function<ApiResponse(const ApiRequest&)>;
  /// Serves one WebSocket client of the stream: sends text messages through `send` (false once
  /// the client is gone) until it returns; `stopping` is set when the server stops.
  using StreamHandler =
      std::function<void(const ApiRequest&, const std::function<bool(const std::string&)>& send,
                         const std::atomic<bool>& stopping)>;

  /// Binds and starts serving; throws InputError when the address cannot be bound. WebSocket
  /// upgrades to the stream (api.hpp) go to `stream`.
  HttpServer(const HttpServerOptions& options, Handler handler, StreamHandler stream = {});
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  unsigned short port() const;
  int connections() const;
  /// Stops accepting, closes every connection and joins their threads.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The token in `file` (its first line), or a new random one written there with mode 0600 when
/// the file does not exist. Throws InputError naming the file when it cannot be read or written.
std::string read_or_create_token(const std::filesystem::path& file);

}  // namespace ballsight
