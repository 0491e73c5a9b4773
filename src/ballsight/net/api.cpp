#include "ballsight/net/api.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <set>

#include "ballsight/camera/image_file.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/base64.hpp"
#include "ballsight/core/csv_fields.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/net/api_channels.hpp"
#include "ballsight/net/api_request.hpp"
#include "ballsight/pipeline/route_json.hpp"
#include "ballsight/pipeline/world_model_json.hpp"
#include "ballsight/service/navigation_json.hpp"

namespace ballsight {
namespace {

using nlohmann::json;

ApiResponse ok(const json& body) {
  return {200, json_text(body)};
}

/// Rejects keys outside `allowed` (a typo must not pass silently).
void only_keys(const json& object, const std::set<std::string>& allowed, const std::string& where) {
  for (const auto& [key, value] : object.items()) {
    if (!allowed.count(key)) api_fail(400, "unknown field '" + key + "'", where);
  }
}

double number(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end()) api_fail(400, std::string("missing field '") + key + "'", where);
  if (!it->is_number()) api_fail(400, "expected a number", where + "." + key);
  const double v = it->get<double>();
  if (!std::isfinite(v)) api_fail(400, "expected a finite number", where + "." + key);
  return v;
}

Vec2 field_point(const json& object, const std::string& where, const FieldRect& area) {
  if (!object.is_object()) api_fail(400, "expected an object {\"x_m\", \"y_m\"}", where);
  only_keys(object, {"x_m", "y_m"}, where);
  const Vec2 p(number(object, "x_m", where), number(object, "y_m", where));
  if (!area.contains(p)) api_fail(422, "outside the field area", where);
  return p;
}

/// The body {"balls": [{"x_m", "y_m"}, ...]}, every ball inside `area`.
std::vector<Vec2> ball_list(const json& body, const FieldRect& area) {
  const auto list = body.find("balls");
  if (list == body.end() || !list->is_array()) api_fail(400, "expected a list", "body.balls");
  std::vector<Vec2> balls;
  for (std::size_t i = 0; i < list->size(); ++i) {
    balls.push_back(field_point((*list)[i], "body.balls[" + std::to_string(i) + "]", area));
  }
  return balls;
}

json point_json(const Vec2& p) {
  return {{"x_m", p.x()}, {"y_m", p.y()}};
}

/// "a=1&b=2" -> the value of `key` as an unsigned integer, or `fallback` when absent.
std::uint64_t query_number(const std::string& query, const std::string& key,
                           std::uint64_t fallback) {
  const std::optional<std::string> text = query_text(query, key);
  if (!text) return fallback;
  std::uint64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || ptr != text->data() + text->size() || text->empty()) {
    api_fail(400, "expected a non-negative integer, got '" + *text + "'", "query " + key);
  }
  return v;
}

/// Adds the update's seq, service id and times to `j`.
void stamp(json& j, const NavigationUpdate& u, const ApiContext& c) {
  j["seq"] = u.seq;
  j["service_id"] = c.hub.service_id();
  j["capture_time_ns"] = u.capture_time_ns;
  j["published_ns"] = u.published_ns;
}

NavigationUpdate latest_or_fail(const NavigationHub& hub) {
  std::optional<NavigationUpdate> u = hub.latest();
  if (!u) api_fail(503, "no update published yet", "service");
  return std::move(*u);
}

// Every route answers (request, query, context).
ApiResponse robot_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  if (request.method == "PUT") {
    require_write(request);
    const json body = parse_body(request.body);
    only_keys(body, {"x_m", "y_m", "heading_deg"}, "body");
    const Vec2 p(number(body, "x_m", "body"), number(body, "y_m", "body"));
    if (!c.area.contains(p)) api_fail(422, "outside the field area", "body");
    c.hub.set_robot({p, rad_from_deg(number(body, "heading_deg", "body"))});
    return ok({{"ok", true}});
  }
  std::optional<Pose2D> pose;
  std::string source = "cameras";
  std::int64_t time_ns = 0;
  if (const auto external = c.hub.robot()) {
    pose = external->value;
    source = "external";
    time_ns = external->set_ns;
  }
  const std::optional<NavigationUpdate> u = c.hub.latest();
  if (u && u->world.robot && (!pose || u->capture_time_ns > time_ns)) {
    pose = u->world.robot->pose;
    source = "cameras";
    time_ns = u->capture_time_ns;
  }
  if (!pose) api_fail(404, "no robot pose yet", "robot");
  return ok({{"x_m", pose->position.x()},
             {"y_m", pose->position.y()},
             {"heading_deg", deg_from_rad(pose->heading_rad)},
             {"source", source},
             {"time_ns", time_ns},
             {"seq", u ? u->seq : 0}});
}

ApiResponse balls_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  if (request.method == "PUT") {
    require_write(request);
    const json body = parse_body(request.body);
    only_keys(body, {"balls"}, "body");
    c.hub.set_balls(ball_list(body, c.area));
    return ok({{"ok", true}});
  }
  json out = json::array();
  const std::optional<NavigationUpdate> u = c.hub.latest();
  const auto external = c.hub.balls();
  std::string source = "cameras";
  if (external && (!u || external->set_ns > u->capture_time_ns)) {
    for (const Vec2& b : external->value) out.push_back(point_json(b));
    source = "external";
  } else if (u) {
    for (const FusedBall& b : u->world.balls) out.push_back(point_json(b.position_m));
  }
  return ok({{"balls", out}, {"source", source}, {"seq", u ? u->seq : 0}});
}

/// `after` of a long-poll or stream. A client that has read nothing (after=0), or read only from
/// another run of the service (`service` names it, or `after` is beyond the latest: it
/// restarted and counts from 1 again), wants the present, not the history: the latest first.
std::uint64_t resume_after(const std::string& query, const ApiContext& c) {
  const std::uint64_t after = query_number(query, "after", 0);
  const std::optional<std::string> service = query_text(query, "service");
  const std::uint64_t latest = c.hub.latest_seq();
  // Beyond the latest: a seq of an earlier run, though the client did not say so.
  const bool restarted =
      (service && *service != c.hub.service_id()) || (latest > 0 && after > latest);
  if (after != 0 && !restarted) return after;
  return latest > 0 ? latest - 1 : 0;
}

/// A long-poll's answer: the first update newer than `after`; nullopt while none is.
std::optional<ApiResponse> poll_answer(std::uint64_t after, const ApiContext& c) {
  const std::optional<NavigationUpdate> u = c.hub.first_after(after);
  if (!u) return std::nullopt;
  return ok(navigation_json(*u, c));
}

ApiResponse navigation_route(const ApiRequest&, const std::string& query, const ApiContext& c) {
  if (!query_text(query, "after")) {
    return ok({{"latest_seq", c.hub.latest_seq()},
               {"acknowledged_seq", c.hub.acknowledged()},
               {"service_id", c.hub.service_id()}});
  }
  const std::uint64_t after = resume_after(query, c);
  const auto wait = std::min<std::uint64_t>(query_number(query, "timeout_ms", 0),
                                            static_cast<std::uint64_t>(c.max_wait.count()));
  if (std::optional<ApiResponse> answer = poll_answer(after, c)) return std::move(*answer);
  ApiResponse pending{204, ""};
  pending.retry = [after, &c] { return poll_answer(after, c); };
  pending.wait = std::chrono::milliseconds(static_cast<std::int64_t>(wait));
  return pending;
}

ApiResponse ack_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  require_write(request);
  const json body = parse_body(request.body);
  only_keys(body, {"seq"}, "body");
  const auto seq = body.find("seq");
  if (seq == body.end() || !seq->is_number_unsigned()) {
    api_fail(400, "expected a non-negative integer", "body.seq");
  }
  try {
    c.hub.acknowledge(seq->get<std::uint64_t>());
  } catch (const InputError& e) {
    api_fail(409, e.what(), "body.seq");
  }
  return ok({{"acknowledged_seq", c.hub.acknowledged()}});
}

/// The body {"seq": N, "ids": [i, ...]}: balls by their index in update N's world model.
std::vector<Vec2> balls_by_id(const json& body, const NavigationHub& hub) {
  const auto seq = body.find("seq");
  if (seq == body.end() || !seq->is_number_unsigned()) {
    api_fail(400, "expected the update's seq the ids belong to", "body.seq");
  }
  const std::uint64_t n = seq->get<std::uint64_t>();
  const std::optional<NavigationUpdate> u = hub.find(n);
  if (!u) api_fail(409, "update " + std::to_string(n) + " is not kept", "body.seq");
  const auto ids = body.find("ids");
  if (ids == body.end() || !ids->is_array()) api_fail(400, "expected a list", "body.ids");
  std::vector<Vec2> positions;
  for (std::size_t i = 0; i < ids->size(); ++i) {
    const json& id = (*ids)[i];
    if (!id.is_number_unsigned() || id.get<std::uint64_t>() >= u->world.balls.size()) {
      api_fail(422, "no such ball in update " + std::to_string(n),
               "body.ids[" + std::to_string(i) + "]");
    }
    positions.push_back(u->world.balls[id.get<std::size_t>()].position_m);
  }
  return positions;
}

ApiResponse collected_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  require_write(request);
  const json body = parse_body(request.body);
  std::vector<Vec2> positions;
  if (body.contains("ids")) {
    only_keys(body, {"seq", "ids", "held"}, "body");
    positions = balls_by_id(body, c.hub);
  } else {
    only_keys(body, {"balls", "held"}, "body");
    positions = ball_list(body, c.area);
  }
  if (const auto held = body.find("held"); held != body.end()) {
    if (!held->is_number_integer() || *held < 0 || *held > 1000) {
      api_fail(400, "expected the balls in the basket, an integer 0 to 1000", "body.held");
    }
    c.hub.set_basket(held->get<int>());
  }
  c.hub.add_collected(positions);
  if (c.on_collected) c.on_collected();
  return ok({{"accepted", positions.size()}});
}

ApiResponse unreachable_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  require_write(request);
  const json body = parse_body(request.body);
  only_keys(body, {"balls", "reason"}, "body");
  const std::vector<Vec2> positions = ball_list(body, c.area);
  const auto reason = body.find("reason");
  if (reason == body.end() || !reason->is_string() || reason->get<std::string>().empty() ||
      reason->get<std::string>().size() > 200) {
    api_fail(400, "expected why, a text of 1 to 200 characters", "body.reason");
  }
  c.hub.mark_unreachable(positions, reason->get<std::string>());
  if (c.on_collected) c.on_collected();  // planned again without them
  return ok({{"accepted", positions.size()}});
}

ApiResponse drive_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  require_write(request);
  if (!c.drive)
    api_fail(404, "not a simulated court: there is no simulated robot to drive", "service");
  const json body = parse_body(request.body);
  only_keys(body, {"seq", "speed_mps", "turn_rate_dps"}, "body");
  const auto seq = body.find("seq");
  if (seq == body.end() || !seq->is_number_unsigned()) {
    api_fail(400, "expected a non-negative integer", "body.seq");
  }
  return ok(c.drive(seq->get<std::uint64_t>(), number(body, "speed_mps", "body"),
                    rad_from_deg(number(body, "turn_rate_dps", "body"))));
}

ApiResponse world_route(const ApiRequest&, const std::string&, const ApiContext& c) {
  const NavigationUpdate u = latest_or_fail(c.hub);
  json j = world_model_json(u.world, c.camera_names);
  stamp(j, u, c);
  return ok(j);
}

ApiResponse plan_route(const ApiRequest&, const std::string&, const ApiContext& c) {
  const NavigationUpdate u = latest_or_fail(c.hub);
  json j = route_json(u.route);
  stamp(j, u, c);
  return ok(j);
}

ApiResponse site_route(const ApiRequest&, const std::string&, const ApiContext& c) {
  return ok(json{{"court", site_court_json(c.court)},
                 {"cameras", c.camera_names},
                 {"ball_radius_m", c.ball_radius_m},
                 {"simulated", static_cast<bool>(c.drive)}});
}

ApiResponse health_route(const ApiRequest&, const std::string&, const ApiContext& c) {
  return ok(c.health ? c.health() : json::object());
}

ApiResponse stream_route(const ApiRequest&, const std::string&, const ApiContext&) {
  api_fail(426, "a WebSocket upgrade is needed", "headers");
}

ApiResponse openapi_route(const ApiRequest&, const std::string&, const ApiContext&) {
  return ok(openapi_document());
}

ApiResponse planner_route(const ApiRequest& request, const std::string&, const ApiContext& c) {
  if (!c.planner || !c.set_planner) api_fail(404, "no planner on this service", "planner");
  if (request.method == "PUT") {
    require_write(request);
    const json body = parse_body(request.body);
    only_keys(body, {"planner"}, "body");
    const auto name = body.find("planner");
    if (name == body.end() || !name->is_string()) {
      api_fail(400, "expected a planner's name", "body.planner");
    }
    const std::optional<PlannerKind> kind = planner_from_name(name->get<std::string>());
    if (!kind || *kind == PlannerKind::exact) {
      api_fail(422,
               "expected priority, nearest or ballsight, got '" + name->get<std::string>() + "'",
               "body.planner");
    }
    c.set_planner(*kind);
  }
  return ok(
      {{"planner", planner_name(c.planner())}, {"choices", {"priority", "nearest", "ballsight"}}});
}

/// GET /api/v1/cameras/{name}/view: the camera's last frame (a JPEG at most 640 px wide, as a
/// data: URL) and its detections in the frame's own pixels.
ApiResponse camera_view_route(const ApiRequest& request, const std::string& path,
                              const ApiContext& c) {
  const std::vector<std::string> parts = path_parts(path, "/api/v1/cameras/");
  if (parts.size() != 2 || parts[1] != "view") api_fail(404, "unknown route", path);
  if (request.method != "GET") api_fail(405, "method " + request.method + " not allowed", path);
  const std::string& name = parts[0];
  const auto camera = std::find(c.camera_names.begin(), c.camera_names.end(), name);
  if (camera == c.camera_names.end()) api_fail(404, "no such camera", "camera " + name);
  const std::optional<CameraView> view =
      c.camera_view ? c.camera_view(static_cast<std::size_t>(camera - c.camera_names.begin()))
                    : std::nullopt;
  if (!view) api_fail(404, "no frame from this camera yet", "camera " + name);
  cv::Mat small = view->frame;
  if (small.cols > 640 && small.rows * 640 / small.cols >= 1) {
    cv::resize(view->frame, small, cv::Size(640, view->frame.rows * 640 / view->frame.cols), 0, 0,
               cv::INTER_AREA);
  }
  json detections = json::array();
  for (const PixelDetection& d : view->detections) {
    detections.push_back({{"object", object_class_name(d.object)},
                          {"x_px", d.center_px.x()},
                          {"y_px", d.center_px.y()},
                          {"radius_px", d.radius_px}});
  }
  return ok({{"camera", name},
             {"seq", view->seq},
             {"capture_time_ns", view->capture_ns},
             {"width", view->frame.cols},
             {"height", view->frame.rows},
             {"detections", detections},
             {"image", "data:image/jpeg;base64," + base64(jpeg_bytes(small, 80, "frame"))}});
}

/// A route of API v1: its path, the methods it takes and what answers it.
struct ApiRoute {
  const char* path;
  std::set<std::string> methods;
  ApiResponse (*answer)(const ApiRequest&, const std::string& query, const ApiContext&);
};

}  // namespace

bool is_stream_target(const std::string& target) {
  return split_target(target).path == "/api/v1/stream";
}

std::variant<StreamSubscription, ApiResponse> stream_subscription(const ApiRequest& request,
                                                                  const ApiContext& c) {
  const std::string query = split_target(request.target).query;
  try {
    StreamSubscription s;
    s.after = resume_after(query, c);
    if (const std::optional<std::string> topics = query_text(query, "topics")) {
      s.navigation = false;
      for (const CsvField& field : split_csv_fields(*topics)) {
        const std::string topic(field.text);
        if (topic == "navigation") {
          s.navigation = true;
        } else if (topic == "world") {
          s.world = true;
        } else if (topic == "health") {
          s.health = true;
        } else {
          api_fail(400, "unknown topic '" + topic + "' (navigation, world or health)",
                   "query topics");
        }
      }
    }
    return s;
  } catch (const ApiError& e) {
    return error_response(e);
  }
}

std::string navigation_message(const NavigationUpdate& update, const ApiContext& c) {
  return json_text(json{{"topic", "navigation"}, {"update", navigation_json(update, c)}});
}

std::string world_message(const NavigationUpdate& update, const ApiContext& c) {
  json j{{"topic", "world"}, {"world", world_model_json(update.world, c.camera_names)}};
  stamp(j, update, c);
  return json_text(j);
}

std::string health_message(const ApiContext& c) {
  return json_text(json{{"topic", "health"},
                        {"time_ns", utc_now_ns()},
                        {"health", c.health ? c.health() : json::object()}});
}

nlohmann::json navigation_json(const NavigationUpdate& update, const ApiContext& c) {
  return navigation_json(update, c.hub.service_id(), c.camera_names);
}

ApiContext::ApiContext(NavigationHub& hub_, std::vector<std::string> camera_names_,
                       const SiteCourt& court_, double ball_radius_m_)
    : hub(hub_),
      camera_names(std::move(camera_names_)),
      court(court_),
      ball_radius_m(ball_radius_m_),
      area(court_.fenced_area()) {}

ApiResponse handle_api(const ApiRequest& request, const ApiContext& c) {
  const RequestTarget target = split_target(request.target);
  const std::string& path = target.path;
  const std::string& query = target.query;
  static const std::vector<ApiRoute> kRoutes{
      {"/api/v1/robot", {"GET", "PUT"}, robot_route},
      {"/api/v1/balls", {"GET", "PUT"}, balls_route},
      {"/api/v1/navigation", {"GET"}, navigation_route},
      {"/api/v1/navigation/ack", {"POST"}, ack_route},
      {"/api/v1/collected", {"POST"}, collected_route},
      {"/api/v1/unreachable", {"POST"}, unreachable_route},
      {"/api/v1/sim/drive", {"PUT"}, drive_route},
      {"/api/v1/world", {"GET"}, world_route},
      {"/api/v1/route", {"GET"}, plan_route},
      {"/api/v1/site", {"GET"}, site_route},
      {"/api/v1/health", {"GET"}, health_route},
      {"/api/v1/stream", {"GET"}, stream_route},
      {"/api/v1/openapi.json", {"GET"}, openapi_route},
      {"/api/v1/planner", {"GET", "PUT"}, planner_route},
  };
  return answer_or_error([&] {
    if (path.starts_with("/api/v1/cameras/")) return camera_view_route(request, path, c);
    const auto route = std::find_if(kRoutes.begin(), kRoutes.end(),
                                    [&](const ApiRoute& r) { return path == r.path; });
    if (route == kRoutes.end()) api_fail(404, "unknown route", path);
    if (!route->methods.count(request.method)) {
      api_fail(405, "method " + request.method + " not allowed", path);
    }
    return route->answer(request, query, c);
  });
}

ApiRoutes api_v1_routes(const ApiContext& context) {
  const auto answer = [&context](const ApiRequest& request) {
    return handle_api(request, context);
  };
  ApiRoutes routes;
  routes.add({.prefix = "/api/v1/", .handler = answer});
  routes.add({.prefix = "/api/v1/cameras/", .handler = answer, .runs_long = true});
  add_api_v1_channels(routes, context);
  return routes;
}

}  // namespace ballsight
