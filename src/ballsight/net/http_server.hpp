#pragma once
// The navigation service's HTTP/1.1 server (Boost.Beast, kept inside http_server.cpp: it compiles
// slowly). One thread accepts; each connection is served by a thread of its own, at most
// `max_connections` at once (a long-poll waits in its connection's thread, so it never holds up
// another client). Requests are bounded (body, header, idle time); the bearer token decides
// whether a request may write, and whether a client on another host may read.

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

  /// Binds and starts serving; throws InputError when the address cannot be bound.
  HttpServer(const HttpServerOptions& options, Handler handler);
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
