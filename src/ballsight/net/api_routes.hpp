#pragma once
// What passes between the transport (http_server.hpp) and the API modules (API v1, api.hpp; the
// calibration pages' APIs, calibration/): a request, its answer, the WebSocket channels a module
// holds, and the routes by which a module says which requests and upgrades are its own and when it
// has published something. The transport parses the wire and asks the routes; it names no API.

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <typeindex>
#include <utility>
#include <variant>
#include <vector>

#include "ballsight/core/json_text.hpp"

namespace ballsight {

struct ApiRequest {
  std::string method;  // "GET", "PUT", "POST", ...
  std::string target;  // path and query, e.g. "/api/v1/navigation?after=3&timeout_ms=500"
  std::string body;
  bool authorized = false;  // carried the service's bearer token
};

struct ApiResponse {
  ApiResponse(int status_ = 200, std::string body_ = {})
      : status(status_), body(std::move(body_)) {}

  int status;
  std::string body;  // JSON (or a web page's file: content_type), or empty for 204
  std::string content_type = "application/json";
  /// A long-poll with nothing to say yet: after each publication (ApiRoutes::events) the
  /// transport asks `retry` again, up to `wait`, and answers with the first answer it gives (this
  /// response, a 204, when none came). Empty: answer now.
  std::function<std::optional<ApiResponse>()> retry;
  std::chrono::milliseconds wait{0};
};

/// The 4xx/5xx answer {"error": what, "where": where}.
ApiResponse api_error(int status, const std::string& what, const std::string& where);

/// The requests an API module answers: those whose path starts with `prefix`.
struct ApiModuleRoute {
  std::string prefix;  // starts and ends with '/', so that it matches whole path segments
  /// Answers one request; never throws for anything a client sends.
  std::function<ApiResponse(const ApiRequest&)> handler;
  /// Its answers take more than a moment (a calibration step, a frame encoded): the transport
  /// answers them off its I/O thread, so that they hold up no other client.
  bool runs_long = false;
};

/// One message to a WebSocket client, text or binary, shared by the clients that get the same.
struct ClientMessage {
  std::shared_ptr<const std::string> data;
  bool binary = false;
};
using ClientMessages = std::vector<ClientMessage>;

/// What one publication (or one health tick) makes for its clients, made once and shared by
/// every channel that asks for the same type and key.
class SharedMessages {
 public:
  template <class T>
  const T& get(const std::string& key, const std::function<T()>& make) {
    std::shared_ptr<const void>& kept = kept_[{std::type_index(typeid(T)), key}];
    if (!kept) kept = std::make_shared<const T>(make());
    return *static_cast<const T*>(kept.get());
  }

 private:
  std::map<std::pair<std::type_index, std::string>, std::shared_ptr<const void>> kept_;
};

/// A WebSocket client's conversation, held by the API module that accepted it. The transport
/// carries its messages (a bounded queue per client: a client that reads too slowly loses its
/// oldest) and calls it on its I/O thread only.
class WebSocketChannel {
 public:
  virtual ~WebSocketChannel() = default;
  /// What the health document's client list calls it ("stream", "foxglove").
  virtual std::string kind() const = 0;
  /// What the client gets as soon as it is connected.
  virtual ClientMessages greeting() = 0;
  /// The answer to a text message of the client.
  virtual ClientMessages on_text(const std::string& message) = 0;
  /// What is new for the client after a publication (ApiRoutes::events).
  virtual ClientMessages on_publish(SharedMessages& shared) = 0;
  /// What the client gets once a second.
  virtual ClientMessages on_tick(SharedMessages& shared) = 0;
};

/// A channel for an upgrade request, with the subprotocol it speaks ("" for none).
struct WebSocketOpened {
  std::unique_ptr<WebSocketChannel> channel;
  std::string subprotocol;
};
/// Opens a channel for an upgrade request (`subprotocols`: the client's Sec-WebSocket-Protocol
/// offer, comma-separated): the channel, the 4xx answer to refuse the upgrade with, or nullopt
/// when the request is not this module's.
using WebSocketOpener = std::function<std::optional<std::variant<WebSocketOpened, ApiResponse>>(
    const ApiRequest& request, const std::string& subprotocols)>;

/// How the transport hears that a module published something (a hub's listener): `listen`
/// registers a callback (called from the publishing thread; it only hands the news over) and
/// returns an id for `unlisten`.
struct PublishEvents {
  std::function<int(std::function<void()>)> listen;
  std::function<void(int)> unlisten;
};

/// The routes the API modules registered. A request goes to the route of the longest prefix its
/// path starts with, so that a module may take a part of another's URLs (/api/v1/omni/ inside
/// /api/v1/). Filled before serving, then only read (from any thread).
class ApiRoutes {
 public:
  /// Throws InputError when the prefix does not start and end with '/', another route has it
  /// already, or the handler is empty.
  void add(ApiModuleRoute route);
  /// The answer of the request's route; a 404 {"error": "unknown route", "where": PATH} when no
  /// route takes it.
  ApiResponse answer(const ApiRequest& request) const;
  /// Whether the route of `target` (path and query) runs long; false when no route takes it.
  bool runs_long(const std::string& target) const;

  /// A module's WebSocket channels; the openers are asked in the order they were added.
  void add_websocket(WebSocketOpener opener);
  /// The channel of the first opener that takes the upgrade request, or the answer refusing it
  /// (404 when none takes it).
  std::variant<WebSocketOpened, ApiResponse> open_websocket(const ApiRequest& request,
                                                            const std::string& subprotocols) const;

  /// Where publications come from (one source: a second replaces the first); empty: none, and
  /// no channel or long-poll hears of any.
  void set_events(PublishEvents events) { events_ = std::move(events); }
  const PublishEvents& events() const { return events_; }

 private:
  /// The route of the longest prefix `target`'s path starts with; null when none.
  const ApiModuleRoute* route_of(const std::string& target) const;

  std::vector<ApiModuleRoute> routes_;  // longest prefix first
  std::vector<WebSocketOpener> openers_;
  PublishEvents events_;
};

}  // namespace ballsight
