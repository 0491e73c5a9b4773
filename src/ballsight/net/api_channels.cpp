#include "ballsight/net/api_channels.hpp"

#include "ballsight/net/api_request.hpp"
#include "ballsight/net/foxglove.hpp"

namespace ballsight {
namespace {

ClientMessage text(std::shared_ptr<const std::string> message) {
  return {std::move(message), false};
}

ClientMessage text(std::string message) {
  return text(std::make_shared<const std::string>(std::move(message)));
}

// The updates newer than `after`, taken from the hub once per publication for every channel
// that has read as far.
const std::vector<NavigationUpdate>& updates_after(std::uint64_t after, const ApiContext& context,
                                                   SharedMessages& shared) {
  return shared.get<std::vector<NavigationUpdate>>("updates after " + std::to_string(after),
                                                   [&] { return context.hub.all_after(after); });
}

// A client of /api/v1/stream: its subscription's topics for every update newer than it has.
class StreamChannel : public WebSocketChannel {
 public:
  StreamChannel(const ApiContext& context, const StreamSubscription& subscription)
      : context_(context), subscription_(subscription), last_seq_(subscription.after) {}

  std::string kind() const override { return "stream"; }
  ClientMessages greeting() override {
    SharedMessages own;
    return on_publish(own);
  }
  ClientMessages on_text(const std::string&) override { return {}; }
  ClientMessages on_publish(SharedMessages& shared) override {
    ClientMessages out;
    for (const NavigationUpdate& u : updates_after(last_seq_, context_, shared)) {
      const std::string seq = std::to_string(u.seq);
      if (subscription_.navigation)
        out.push_back(text(shared.get<std::shared_ptr<const std::string>>("navigation " + seq, [&] {
          return std::make_shared<const std::string>(navigation_message(u, context_));
        })));
      if (subscription_.world)
        out.push_back(text(shared.get<std::shared_ptr<const std::string>>("world " + seq, [&] {
          return std::make_shared<const std::string>(world_message(u, context_));
        })));
      last_seq_ = u.seq;
    }
    return out;
  }
  ClientMessages on_tick(SharedMessages& shared) override {
    if (!subscription_.health) return {};
    return {text(shared.get<std::shared_ptr<const std::string>>(
        "health", [&] { return std::make_shared<const std::string>(health_message(context_)); }))};
  }

 private:
  const ApiContext& context_;
  const StreamSubscription subscription_;
  std::uint64_t last_seq_;  // the newest update sent
};

// A Foxglove client: its subscriptions' message data for every update after it connected.
class FoxgloveChannel : public WebSocketChannel {
 public:
  explicit FoxgloveChannel(const ApiContext& context)
      : context_(context), session_(context), last_seq_(context.hub.latest_seq()) {}

  std::string kind() const override { return "foxglove"; }
  ClientMessages greeting() override {
    ClientMessages out;
    for (std::string& m : session_.greeting()) out.push_back(text(std::move(m)));
    return out;
  }
  ClientMessages on_text(const std::string& message) override {
    // A new subscription gets the update last sent (not the hub's latest, which the next
    // publication is about to send: it would arrive twice).
    const std::optional<NavigationUpdate> handled =
        last_seq_ > 0 ? context_.hub.first_after(last_seq_ - 1) : std::nullopt;
    FoxgloveOutput answer = session_.on_text(message, handled);
    ClientMessages out;
    for (std::string& m : answer.text) out.push_back(text(std::move(m)));
    for (std::string& m : answer.binary)
      out.push_back({std::make_shared<const std::string>(std::move(m)), true});
    return out;
  }
  ClientMessages on_publish(SharedMessages& shared) override {
    ClientMessages out;
    for (const NavigationUpdate& u : updates_after(last_seq_, context_, shared)) {
      for (std::string& f : session_.frames(u))
        out.push_back({std::make_shared<const std::string>(std::move(f)), true});
      last_seq_ = u.seq;
    }
    return out;
  }
  ClientMessages on_tick(SharedMessages&) override { return {}; }

 private:
  const ApiContext& context_;
  FoxgloveSession session_;
  std::uint64_t last_seq_;  // the newest update sent
};

}  // namespace

void add_api_v1_channels(ApiRoutes& routes, const ApiContext& context) {
  routes.add_websocket([&context](const ApiRequest&, const std::string& subprotocols)
                           -> std::optional<std::variant<WebSocketOpened, ApiResponse>> {
    const std::string foxglove = foxglove_subprotocol(subprotocols);
    if (foxglove.empty()) return std::nullopt;
    return WebSocketOpened{std::make_unique<FoxgloveChannel>(context), foxglove};
  });
  routes.add_websocket(
      [&context](const ApiRequest& request,
                 const std::string&) -> std::optional<std::variant<WebSocketOpened, ApiResponse>> {
        if (!split_target(request.target).path.starts_with("/api/v1/")) return std::nullopt;
        if (!is_stream_target(request.target))
          return api_error(404, "no WebSocket here (the stream is /api/v1/stream)", request.target);
        auto subscription = stream_subscription(request, context);
        if (auto* s = std::get_if<StreamSubscription>(&subscription))
          return WebSocketOpened{std::make_unique<StreamChannel>(context, *s), ""};
        return std::get<ApiResponse>(subscription);
      });
  NavigationHub& hub = context.hub;
  routes.set_events({[&hub](std::function<void()> published) {
                       return hub.add_listener([published](std::uint64_t) { published(); });
                     },
                     [&hub](int id) { hub.remove_listener(id); }});
}

}  // namespace ballsight
