#include <charconv>
#include <sstream>

#include "ballsight/world/site.hpp"

namespace ballsight {
namespace {

// The shortest text that reads back as the same double.
std::string number(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return {text, end};
}

// A YAML single-quoted scalar: any text, its quotes doubled.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string rgb(const Rgb& c) {
  std::string out = "[";
  out += std::to_string(c.r);
  out += ", ";
  out += std::to_string(c.g);
  out += ", ";
  out += std::to_string(c.b);
  return out + "]";
}

template <class V>
std::string vector_text(const V& v) {
  std::string out = "[";
  for (int i = 0; i < v.size(); ++i) out += (i ? ", " : "") + number(v[i]);
  return out + "]";
}

std::string source_text(const SiteCamera& camera) {
  const CameraSource& s = camera.source;
  switch (s.kind) {
    case CameraSource::Kind::device:
      return std::string("{device: ").append(std::to_string(s.device)).append("}");
    case CameraSource::Kind::url:
      return "{url: " + quoted(s.url) + "}";
    case CameraSource::Kind::folder:
      return "{folder: " + quoted(s.path.string()) + "}";
    case CameraSource::Kind::file:
      break;
  }
  return "{file: " + quoted(s.path.empty() ? camera.name + ".png" : s.path.string()) + "}";
}

}  // namespace

std::string site_file_text(const Site& site) {
  std::ostringstream out;
  const SiteCourt& c = site.court;
  out << "court:\n"
      << "  length_m: " << number(c.length_m) << "\n"
      << "  width_m: " << number(c.width_m) << "\n"
      << "  area_length_m: " << number(c.area_length_m) << "\n"
      << "  area_width_m: " << number(c.area_width_m) << "\n"
      << "  net: " << (c.net ? "true" : "false") << "\n"
      << "  net_posts_outside_m: " << number(c.net_posts_outside_m) << "\n"
      << "  net_height_posts_m: " << number(c.net_height_posts_m) << "\n"
      << "  net_height_centre_m: " << number(c.net_height_centre_m) << "\n"
      << "  net_clearance_m: " << number(c.net_clearance_m) << "\n"
      << "  net_post_clearance_m: " << number(c.net_post_clearance_m) << "\n"
      << "  net_travel_clearance_m: " << number(c.net_travel_clearance_m) << "\n"
      << "  fence_lane_m: " << number(c.fence_lane_m) << "\n"
      << "ball_radius_m: " << number(site.ball_radius_m) << "\n"
      << "reference_balls:\n"
      << "  radius_m: " << number(site.reference_ball_radius_m) << "\n"
      << "  positions_m:\n";
  for (const ReferenceBall& b : site.reference_balls)
    out << "    " << quoted(b.name) << ": " << vector_text(b.floor_position_m) << "\n";
  const SiteColours& k = site.colours;
  out << "colours:\n"
      << "  ball: " << rgb(k.ball) << "\n"
      << "  reference_ball: " << rgb(k.reference_ball) << "\n"
      << "  robot_front: " << rgb(k.robot_front) << "\n"
      << "  robot_back: " << rgb(k.robot_back) << "\n";
  const SiteRobot& r = site.robot;
  out << "robot:\n"
      << "  marker_radius_m: " << number(r.marker_radius_m) << "\n"
      << "  marker_height_m: " << number(r.marker_height_m) << "\n"
      << "  collector_width_m: " << number(r.collector_width_m) << "\n"
      << "  collector_x_m: " << number(r.collector_x_m) << "\n"
      << "  max_speed_mps: " << number(r.max_speed_mps) << "\n"
      << "  turn_rate_dps: " << number(r.turn_rate_dps) << "\n"
      << "  max_accel_mps2: " << number(r.max_accel_mps2) << "\n"
      << "  turn_accel_dps2: " << number(r.turn_accel_dps2) << "\n"
      << "  capacity: " << r.capacity << "\n"
      << "  unload_s: " << number(r.unload_s) << "\n";
  if (r.unload_m) out << "  unload_m: " << vector_text(*r.unload_m) << "\n";
  out << "cameras:\n";
  for (const SiteCamera& camera : site.cameras) {
    const std::string calibration =
        camera.calibration_file.empty() ? camera.name + ".yml" : camera.calibration_file.string();
    out << "  - name: " << quoted(camera.name) << "\n"
        << "    source: " << source_text(camera) << "\n"
        << "    calibration: " << quoted(calibration) << "\n";
    if (camera.position_hint_m)
      out << "    position_hint_m: " << vector_text(*camera.position_hint_m) << "\n";
  }
  return out.str();
}

}  // namespace ballsight
