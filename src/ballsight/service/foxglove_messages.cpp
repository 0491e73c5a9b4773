#include "ballsight/service/foxglove_messages.hpp"

#include <cmath>

#include "ballsight/core/base64.hpp"

namespace ballsight::foxglove {
namespace {

using nlohmann::json;

json object_schema(const json& properties) {
  return {{"type", "object"}, {"properties", properties}};
}

json array_of(const json& items) {
  return {{"type", "array"}, {"items", items}};
}

json number_schema() {
  return {{"type", "number"}};
}

json time_schema() {
  return object_schema({{"sec", {{"type", "integer"}}}, {"nsec", {{"type", "integer"}}}});
}

json pose_schema() {
  return object_schema(
      {{"position",
        object_schema({{"x", number_schema()}, {"y", number_schema()}, {"z", number_schema()}})},
       {"orientation", object_schema({{"x", number_schema()},
                                      {"y", number_schema()},
                                      {"z", number_schema()},
                                      {"w", number_schema()}})}});
}

json color_schema() {
  return object_schema({{"r", number_schema()},
                        {"g", number_schema()},
                        {"b", number_schema()},
                        {"a", number_schema()}});
}

json point(double x, double y, double z = 0.0) {
  return {{"x", x}, {"y", y}, {"z", z}};
}

/// A pose at (x, y, z) heading `yaw` about the vertical.
json pose(double x, double y, double z, double yaw) {
  return {{"position", point(x, y, z)},
          {"orientation",
           {{"x", 0.0}, {"y", 0.0}, {"z", std::sin(yaw / 2.0)}, {"w", std::cos(yaw / 2.0)}}}};
}

json color(double r, double g, double b, double a = 1.0) {
  return {{"r", r}, {"g", g}, {"b", b}, {"a", a}};
}

json line(int type, const std::vector<Vec2>& points, double thickness, const json& rgba) {
  json pts = json::array();
  for (const Vec2& p : points) pts.push_back(point(p.x(), p.y()));
  return {{"type", type},
          {"pose", pose(0, 0, 0, 0)},
          {"thickness", thickness},
          {"scale_invariant", false},
          {"points", pts},
          {"color", rgba},
          {"colors", json::array()},
          {"indices", json::array()}};
}

json entity(const std::string& id, std::int64_t time_ns) {
  json e{{"timestamp", stamp(time_ns)}, {"frame_id", kCourtFrame}, {"id", id},
         {"lifetime", stamp(0)},        {"frame_locked", false},   {"metadata", json::array()}};
  for (const char* kind :
       {"arrows", "cubes", "spheres", "cylinders", "lines", "triangles", "texts", "models"}) {
    e[kind] = json::array();
  }
  return e;
}

std::vector<Vec2> rectangle(double length, double width) {
  const double x = length / 2.0, y = width / 2.0;
  return {{-x, -y}, {x, -y}, {x, y}, {-x, y}};
}

}  // namespace

json scene_update_schema() {
  const json vector3 =
      object_schema({{"x", number_schema()}, {"y", number_schema()}, {"z", number_schema()}});
  const json shape =
      object_schema({{"pose", pose_schema()}, {"size", vector3}, {"color", color_schema()}});
  const json line = object_schema({{"type", {{"type", "integer"}}},
                                   {"pose", pose_schema()},
                                   {"thickness", number_schema()},
                                   {"scale_invariant", {{"type", "boolean"}}},
                                   {"points", array_of(vector3)},
                                   {"color", color_schema()}});
  const json entity = object_schema({{"timestamp", time_schema()},
                                     {"frame_id", {{"type", "string"}}},
                                     {"id", {{"type", "string"}}},
                                     {"lifetime", time_schema()},
                                     {"frame_locked", {{"type", "boolean"}}},
                                     {"spheres", array_of(shape)},
                                     {"cubes", array_of(shape)},
                                     {"lines", array_of(line)}});
  return object_schema({{"deletions", array_of(object_schema({{"id", {{"type", "string"}}}}))},
                        {"entities", array_of(entity)}});
}

json pose_in_frame_schema() {
  return object_schema(
      {{"timestamp", time_schema()}, {"frame_id", {{"type", "string"}}}, {"pose", pose_schema()}});
}

json poses_in_frame_schema() {
  return object_schema({{"timestamp", time_schema()},
                        {"frame_id", {{"type", "string"}}},
                        {"poses", array_of(pose_schema())}});
}

json compressed_image_schema() {
  return object_schema({{"timestamp", time_schema()},
                        {"frame_id", {{"type", "string"}}},
                        {"data", {{"type", "string"}, {"contentEncoding", "base64"}}},
                        {"format", {{"type", "string"}}}});
}

json image_annotations_schema() {
  const json point2 = object_schema({{"x", number_schema()}, {"y", number_schema()}});
  const json circle = object_schema({{"timestamp", time_schema()},
                                     {"position", point2},
                                     {"diameter", number_schema()},
                                     {"thickness", number_schema()},
                                     {"fill_color", color_schema()},
                                     {"outline_color", color_schema()}});
  return object_schema({{"circles", array_of(circle)},
                        {"points", {{"type", "array"}}},
                        {"texts", {{"type", "array"}}}});
}

json navigation_update_schema() {
  return object_schema({{"seq", {{"type", "integer"}}},
                        {"service_id", {{"type", "string"}}},
                        {"capture_time_ns", {{"type", "integer"}}},
                        {"published_ns", {{"type", "integer"}}},
                        {"world", {{"type", "object"}}},
                        {"route", {{"type", "object"}}},
                        {"given_up", {{"type", "array"}}}});
}

json stamp(std::int64_t time_ns) {
  return {{"sec", time_ns / 1'000'000'000}, {"nsec", time_ns % 1'000'000'000}};
}

json court_scene(const SiteCourt& court, std::int64_t time_ns) {
  json e = entity("court", time_ns);
  constexpr int kLineLoop = 1, kLineList = 2;
  e["lines"].push_back(line(kLineLoop, rectangle(court.area_length_m, court.area_width_m), 0.05,
                            color(0.6, 0.6, 0.6)));
  e["lines"].push_back(
      line(kLineLoop, rectangle(court.length_m, court.width_m), 0.05, color(1, 1, 1)));
  if (court.net) {
    const double y = court.width_m / 2.0 + court.net_posts_outside_m;
    e["lines"].push_back(line(kLineList, {{0.0, -y}, {0.0, y}}, 0.08, color(0.1, 0.1, 0.1)));
  }
  return {{"deletions", json::array()}, {"entities", {e}}};
}

json balls_scene(const WorldModel& world, double ball_radius_m, std::int64_t time_ns) {
  json e = entity("balls", time_ns);
  const double d = 2.0 * ball_radius_m;
  for (const FusedBall& b : world.balls) {
    e["spheres"].push_back({{"pose", pose(b.position_m.x(), b.position_m.y(), ball_radius_m, 0)},
                            {"size", point(d, d, d)},
                            {"color", color(0.8, 1.0, 0.1)}});
  }
  return {{"deletions", json::array()}, {"entities", {e}}};
}

std::optional<json> robot_pose(const WorldModel& world, std::int64_t time_ns) {
  if (!world.robot) return std::nullopt;
  const Pose2D& p = world.robot->pose;
  return json{{"timestamp", stamp(time_ns)},
              {"frame_id", kCourtFrame},
              {"pose", pose(p.position.x(), p.position.y(), 0.0, p.heading_rad)}};
}

json route_poses(const Route& route, std::int64_t time_ns) {
  json poses = json::array();
  const std::vector<Vec2>& w = route.waypoints_m;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Vec2 along = i + 1 < w.size() ? Vec2(w[i + 1] - w[i])
                       : i > 0          ? Vec2(w[i] - w[i - 1])
                                        : Vec2(1, 0);
    poses.push_back(pose(w[i].x(), w[i].y(), 0.0, std::atan2(along.y(), along.x())));
  }
  return {{"timestamp", stamp(time_ns)}, {"frame_id", kCourtFrame}, {"poses", poses}};
}

json compressed_image(std::string_view bytes, std::string_view format, const std::string& frame_id,
                      std::int64_t time_ns) {
  return {{"timestamp", stamp(time_ns)},
          {"frame_id", frame_id},
          {"data", base64(bytes)},
          {"format", format}};
}

json image_annotations(const std::vector<PixelDetection>& detections, std::int64_t time_ns) {
  json circles = json::array();
  for (const PixelDetection& d : detections) {
    const json outline = d.object == ObjectClass::ball                 ? color(0.8, 1.0, 0.1)
                         : d.object == ObjectClass::robot_front_marker ? color(1, 0.2, 0.2)
                         : d.object == ObjectClass::robot_back_marker  ? color(0.2, 0.4, 1)
                                                                       : color(0.6, 0.6, 0.6);
    circles.push_back({{"timestamp", stamp(time_ns)},
                       // Foxglove's origin is the top-left pixel's corner, ours its centre.
                       {"position", {{"x", d.center_px.x() + 0.5}, {"y", d.center_px.y() + 0.5}}},
                       {"diameter", 2.0 * d.radius_px},
                       {"thickness", 2.0},
                       {"fill_color", color(0, 0, 0, 0)},
                       {"outline_color", outline}});
  }
  return {{"circles", circles}, {"points", json::array()}, {"texts", json::array()}};
}

}  // namespace ballsight::foxglove
