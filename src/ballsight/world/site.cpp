#include "ballsight/world/site.hpp"

#include <cmath>
#include <set>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/text_format.hpp"
#include "ballsight/core/yaml_reader.hpp"

namespace ballsight {

namespace fs = std::filesystem;

std::string_view camera_source_kind_name(CameraSource::Kind kind) {
  switch (kind) {
    case CameraSource::Kind::file:
      return "file";
    case CameraSource::Kind::folder:
      return "folder";
    case CameraSource::Kind::device:
      return "device";
    case CameraSource::Kind::url:
      return "url";
  }
  return "?";
}

Vec3 Site::reference_center_in_field(const ReferenceBall& ball) const {
  return {ball.floor_position_m.x(), ball.floor_position_m.y(), reference_ball_radius_m};
}

Vec2 Site::unload_point() const {
  return robot.unload_m.value_or(Vec2(court.area_length_m / 2.0 - 1.5, 0.0));
}

namespace {

// Reads an optional positive length into `out` (keeps the default when absent).
void read_length(YamlMap& map, const std::string& key, double& out) {
  if (const auto v = map.find(key)) {
    out = v->number();
    if (!(out > 0.0)) v->fail("must be positive, got " + v->node().Scalar());
  }
}

void read_non_negative(YamlMap& map, const std::string& key, double& out) {
  if (const auto v = map.find(key)) {
    out = v->number();
    if (!(out >= 0.0)) v->fail("must not be negative, got " + v->node().Scalar());
  }
}

void read_rgb(YamlMap& map, const std::string& key, Rgb& out) {
  if (const auto v = map.find(key)) {
    const std::vector<int> c = v->integers(3, 0, 255);
    out = {static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
           static_cast<std::uint8_t>(c[2])};
  }
}

SiteCourt read_court(YamlMap map) {
  SiteCourt court;
  read_length(map, "length_m", court.length_m);
  read_length(map, "width_m", court.width_m);
  read_length(map, "area_length_m", court.area_length_m);
  read_length(map, "area_width_m", court.area_width_m);
  if (const auto v = map.find("net")) court.net = v->flag();
  read_length(map, "net_posts_outside_m", court.net_posts_outside_m);
  read_length(map, "net_height_posts_m", court.net_height_posts_m);
  read_length(map, "net_height_centre_m", court.net_height_centre_m);
  read_non_negative(map, "net_clearance_m", court.net_clearance_m);
  read_non_negative(map, "net_post_clearance_m", court.net_post_clearance_m);
  read_non_negative(map, "net_travel_clearance_m", court.net_travel_clearance_m);
  read_non_negative(map, "fence_lane_m", court.fence_lane_m);
  map.finish();
  if (court.net_travel_clearance_m < court.net_clearance_m) {
    map.value().fail("net_travel_clearance_m must not be less than net_clearance_m");
  }
  if (court.area_length_m < court.length_m || court.area_width_m < court.width_m) {
    map.value().fail("area_length_m x area_width_m must contain the court");
  }
  if (2.0 * court.fence_lane_m >= std::min(court.area_length_m, court.area_width_m)) {
    map.value().fail(
        "fence_lane_m must leave room inside the fence (less than half of "
        "area_width_m)");
  }
  const double beyond_post =
      court.width_m / 2.0 + court.net_posts_outside_m + court.net_post_clearance_m;
  if (court.net && (court.area_width_m / 2.0 <= beyond_post ||
                    court.area_length_m / 2.0 <= court.net_travel_clearance_m)) {
    map.value().fail("area_width_m must leave room to drive round the net posts (more than " +
                     fixed(2.0 * beyond_post, 2) + " m)");
  }
  return court;
}

SiteColours read_colours(YamlMap map) {
  SiteColours colours;
  read_rgb(map, "ball", colours.ball);
  read_rgb(map, "reference_ball", colours.reference_ball);
  read_rgb(map, "robot_front", colours.robot_front);
  read_rgb(map, "robot_back", colours.robot_back);
  map.finish();
  return colours;
}

// An unload point clear of the fence's lane and of the net's.
bool clear_to_unload(const SiteCourt& court, const Vec2& p) {
  const double x = std::abs(p.x()), y = std::abs(p.y());
  return x <= court.area_length_m / 2.0 - court.fence_lane_m &&
         y <= court.area_width_m / 2.0 - court.fence_lane_m &&
         !(court.net && x < court.net_travel_clearance_m);
}

SiteRobot read_robot(YamlMap map, const SiteCourt& court) {
  SiteRobot robot;
  read_length(map, "marker_radius_m", robot.marker_radius_m);
  read_length(map, "marker_height_m", robot.marker_height_m);
  read_length(map, "collector_width_m", robot.collector_width_m);
  read_non_negative(map, "collector_x_m", robot.collector_x_m);
  read_length(map, "max_speed_mps", robot.max_speed_mps);
  read_length(map, "turn_rate_dps", robot.turn_rate_dps);
  read_length(map, "max_accel_mps2", robot.max_accel_mps2);
  read_length(map, "turn_accel_dps2", robot.turn_accel_dps2);
  if (const auto v = map.find("capacity")) {
    robot.capacity = v->integer();
    if (robot.capacity < 1 || robot.capacity > 1000) {
      v->fail("must be 1 to 1000 balls, got " + v->node().Scalar());
    }
  }
  if (const auto v = map.find("unload_m")) {
    const std::vector<double> p = v->numbers(2);
    robot.unload_m = Vec2(p[0], p[1]);
    if (!clear_to_unload(court, *robot.unload_m)) {
      v->fail("must be clear of the fence's lane and of the net's (unload_m " + fixed(p[0], 2) +
              ", " + fixed(p[1], 2) + ")");
    }
  }
  read_non_negative(map, "unload_s", robot.unload_s);
  map.finish();
  return robot;
}

void read_reference_balls(YamlMap map, Site& site) {
  read_length(map, "radius_m", site.reference_ball_radius_m);
  YamlMap positions = map.at("positions_m").map();
  for (const auto& [name, value] : positions.entries()) {
    const std::vector<double> xy = value.numbers(2);
    site.reference_balls.push_back({name, Vec2(xy[0], xy[1])});
  }
  positions.finish();
  map.finish();
  if (site.reference_balls.size() < 4) {
    positions.value().fail("needs at least 4 reference balls, got " +
                           std::to_string(site.reference_balls.size()));
  }
}

CameraSource read_source(YamlMap map, const fs::path& base) {
  CameraSource source;
  int kinds = 0;
  if (const auto v = map.find("file")) {
    source = {CameraSource::Kind::file, base / v->text(), 0, {}};
    ++kinds;
  }
  if (const auto v = map.find("folder")) {
    source = {CameraSource::Kind::folder, base / v->text(), 0, {}};
    ++kinds;
  }
  if (const auto v = map.find("device")) {
    source = {CameraSource::Kind::device, {}, v->integer(), {}};
    if (source.device < 0) v->fail("must be a non-negative device index");
    ++kinds;
  }
  if (const auto v = map.find("url")) {
    source = {CameraSource::Kind::url, {}, 0, v->text()};
    const std::string& url = source.url;
    if (url.rfind("rtsp://", 0) != 0 && url.rfind("http://", 0) != 0 &&
        url.rfind("https://", 0) != 0) {
      v->fail("expected an rtsp://, http:// or https:// address");
    }
    ++kinds;
  }
  map.finish();
  if (kinds != 1) map.value().fail("expected exactly one of file, folder, device, url");
  return source;
}

SiteCamera read_camera(YamlMap map, const fs::path& base) {
  SiteCamera camera;
  camera.name = map.at("name").text();
  camera.source = read_source(map.at("source").map(), base);
  camera.calibration_file = base / map.at("calibration").text();
  if (const auto v = map.find("position_hint_m")) {
    const std::vector<double> p = v->numbers(3);
    camera.position_hint_m = Vec3(p[0], p[1], p[2]);
  }
  map.finish();
  return camera;
}

void read_cameras(const YamlValue& list, Site& site, const fs::path& base) {
  const std::vector<YamlValue> items = list.list();
  if (items.empty()) list.fail("needs at least one camera");
  std::set<std::string> names;
  std::set<fs::path> files;
  for (const YamlValue& item : items) {
    site.cameras.push_back(read_camera(item.map(), base));
    const SiteCamera& c = site.cameras.back();
    if (!names.insert(c.name).second) item.fail("repeats camera name '" + c.name + "'");
    if (!files.insert(c.calibration_file.lexically_normal()).second) {
      item.fail("repeats calibration file " + c.calibration_file.string());
    }
  }
}

}  // namespace

Site parse_site(std::string_view text, const fs::path& file) {
  const fs::path base = file.has_parent_path() ? file.parent_path() : fs::path();
  YamlMap root = YamlMap::parse(text, file.string());
  Site site;
  site.file = file;
  if (const auto v = root.find("court")) site.court = read_court(v->map());
  read_length(root, "ball_radius_m", site.ball_radius_m);
  read_reference_balls(root.at("reference_balls").map(), site);
  if (const auto v = root.find("colours")) site.colours = read_colours(v->map());
  if (const auto v = root.find("robot")) site.robot = read_robot(v->map(), site.court);
  read_cameras(root.at("cameras"), site, base);
  root.finish();
  if (!clear_to_unload(site.court, site.unload_point())) {
    throw InputError(file.string() + ": the default unload point (" +
                     fixed(site.unload_point().x(), 2) + ", " + fixed(site.unload_point().y(), 2) +
                     ") is not clear of the fence's lane: give robot.unload_m");
  }
  return site;
}

Site read_site(const fs::path& file) {
  return parse_site(read_file(file, kMaxDocumentBytes), file);
}

}  // namespace ballsight
