#pragma once
// API v1 of the navigation service, an API module (api_routes.hpp): one request in, one response
// out (docs/robot-link.md; the routes are listed by `openapi_document()`). The HTTP server
// (http_server.hpp) parses the wire and says whether the request carried the token; everything a
// client sends is checked here, and every bad request gets a 4xx with {"error", "where"}.

#include <chrono>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ballsight/core/field_rect.hpp"
#include "ballsight/net/api_routes.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/service/camera_view.hpp"
#include "ballsight/service/navigation_hub.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct ApiContext {
  ApiContext(NavigationHub& hub_, std::vector<std::string> camera_names_, const SiteCourt& court_,
             double ball_radius_m_);

  NavigationHub& hub;
  std::vector<std::string> camera_names;
  SiteCourt court;
  double ball_radius_m;
  FieldRect area;                          // the court's fenced area: positions sent lie in it
  std::function<nlohmann::json()> health;  // the service's health document
  std::function<void()> on_collected;      // balls were reported collected: re-plan now
  /// The simulated court only: a simulated robot's command for update `seq` (PUT
  /// /api/v1/sim/drive); answers its collector's count. Empty elsewhere (404).
  std::function<nlohmann::json(std::uint64_t seq, double speed_mps, double turn_rate_rps)> drive;
  /// Camera k's last frame and detections (GET /api/v1/cameras/{name}/view); empty: none.
  std::function<std::optional<CameraView>(std::size_t camera)> camera_view;
  /// The planner of the next plans (GET and PUT /api/v1/planner); empty: not offered (404).
  std::function<PlannerKind()> planner;
  std::function<void(PlannerKind)> set_planner;
  std::chrono::milliseconds max_wait{30000};  // cap on a long-poll's timeout_ms
};

/// Answers one request without waiting. Never throws for anything a client sends.
ApiResponse handle_api(const ApiRequest& request, const ApiContext& context);
/// API v1 on `context` (which must outlive them) as the routes of a service: /api/v1/, and the
/// camera views (/api/v1/cameras/), which encode a frame and so run long; the stream's and
/// Foxglove's WebSocket channels and the hub's publications (api_channels.hpp). The calibration
/// pages' APIs add their own (calibration/).
ApiRoutes api_v1_routes(const ApiContext& context);

/// What a WebSocket client of /api/v1/stream[?after=SEQ&topics=navigation,world,health&service=ID]
/// asked for: every update newer than SEQ (from the latest when SEQ is 0 or ID is not this
/// service's: it restarted) as the chosen topics, and the health document once a second.
struct StreamSubscription {
  std::uint64_t after = 0;
  bool navigation = true;
  bool world = false;
  bool health = false;
};
/// Whether `target` is the stream.
bool is_stream_target(const std::string& target);
/// The subscription of a stream request, or the 4xx to refuse its upgrade with.
std::variant<StreamSubscription, ApiResponse> stream_subscription(const ApiRequest& request,
                                                                  const ApiContext& context);
/// The stream's messages: {"topic": "navigation", "update": {...}}, {"topic": "world", "seq",
/// "service_id", "capture_time_ns", "world": {...}} and {"topic": "health", "time_ns", "health":
/// {...}}. A client finds updates it missed (it read too slowly) as gaps in seq.
std::string navigation_message(const NavigationUpdate& update, const ApiContext& context);
std::string world_message(const NavigationUpdate& update, const ApiContext& context);
std::string health_message(const ApiContext& context);

/// The OpenAPI 3 document of API v1.
const nlohmann::json& openapi_document();

/// The JSON of one update (service/navigation_json.hpp) with this service's id and camera names.
nlohmann::json navigation_json(const NavigationUpdate& update, const ApiContext& context);

}  // namespace ballsight
