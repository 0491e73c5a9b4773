#pragma once
// The navigation service's HTTP/1.1 and WebSocket server (Boost.Beast, kept inside
// http_server.cpp: it compiles slowly). One I/O thread serves every connection with coroutines:
// requests, long-polls parked until a publication answers them (or their time is up), and
// WebSocket clients, each with a bounded queue of messages: a client that reads too slowly loses
// its oldest messages (counted in `clients()`), never holds up another client or the publisher,
// which only tells the I/O thread that something was published. What is said is the API modules'
// (api_routes.hpp): a request goes to the route a module registered (on a worker thread when the
// route runs long), an upgrade to the channel a module opens, and a publication to every channel
// and parked long-poll. The server names no API. Requests are bounded (body, header, idle time,
// connections); the bearer token decides whether a request may write, and whether a client on
// another host may read.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ballsight/net/api_routes.hpp"

namespace ballsight {

struct HttpServerOptions {
  std::string address = "127.0.0.1";
  unsigned short port = 8080;  // 0: a free port (HttpServer::port() says which)
  std::string token;           // writes need "Authorization: Bearer <token>"
  bool open_reads = false;     // reads from other hosts need no token
  std::size_t body_limit = 64 * 1024;
  std::size_t header_limit = 8 * 1024;
  int max_connections = 256;
  std::chrono::seconds idle_timeout{30};
  std::size_t client_queue = 128;  // messages waiting for one WebSocket client, at most
  /// The kernel's send buffer of a WebSocket client (SO_SNDBUF): small, so that a slow client's
  /// backlog waits in its queue, where the oldest is dropped, not in the kernel, where it ages.
  int client_send_buffer = 64 * 1024;
  /// The web pages' folder (web_files.hpp), served at / and /web/; empty: API only.
  std::filesystem::path web_root;
  /// The npm folder the pages' libraries come from (web_files.hpp); empty: none.
  std::filesystem::path node_modules;

  /// Throws InputError naming the first invalid field.
  void validate() const;
};

/// One WebSocket client, as the health document shows it.
struct ClientStats {
  std::uint64_t id = 0;
  std::string kind;    // "stream" or "foxglove"
  std::string remote;  // address:port
  std::uint64_t sent = 0;
  std::uint64_t dropped = 0;  // messages dropped because the client read too slowly
  std::size_t queued = 0;
};

/// [{"id", "kind", "remote", "sent", "dropped", "queued"}, ...]
nlohmann::json clients_json(const std::vector<ClientStats>& clients);

class HttpServer {
 public:
  /// Binds and starts serving: every request, upgrade and publication by `routes` (whose modules
  /// must outlive the server). Throws InputError when the address cannot be bound.
  HttpServer(const HttpServerOptions& options, ApiRoutes routes);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  unsigned short port() const;
  int connections() const;
  std::vector<ClientStats> clients() const;
  /// Stops accepting, closes every connection and joins the I/O thread.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ballsight
