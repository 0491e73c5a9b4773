#include "ballsight/sim/omni_truth_json.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight::sim {

using json = nlohmann::ordered_json;

namespace {

json vec2_json(const Vec2& v) {
  return json::array({v.x(), v.y()});
}
json optional_vec2_json(const std::optional<Vec2>& v) {
  return v ? vec2_json(*v) : json(nullptr);
}
json bgr_json(const cv::Vec3b& c) {
  return json::array({c[0], c[1], c[2]});
}

json field_json(const MslFieldSpec& f) {
  return {{"width_m", f.width_m},
          {"length_m", f.length_m},
          {"line_width_m", f.line_width_m},
          {"center_circle_radius_m", f.center_circle_radius_m},
          {"spot_radius_m", f.spot_radius_m},
          {"goal_area_width_m", f.goal_area_width_m},
          {"goal_area_depth_m", f.goal_area_depth_m},
          {"penalty_area_width_m", f.penalty_area_width_m},
          {"penalty_area_depth_m", f.penalty_area_depth_m},
          {"penalty_spot_distance_m", f.penalty_spot_distance_m},
          {"corner_arc_radius_m", f.corner_arc_radius_m},
          {"carpet_margin_m", f.carpet_margin_m},
          {"carpet_bgr", bgr_json(f.carpet_bgr)},
          {"line_bgr", bgr_json(f.line_bgr)},
          {"floor_bgr", bgr_json(f.floor_bgr)},
          {"carpet_texture_levels", f.carpet_texture_levels}};
}

json placed_json(const Vec2& in_field, const Vec2& in_robot, double radius_m,
                 const RobotRange& range) {
  return {{"position_in_field_m", vec2_json(in_field)},
          {"position_in_robot_m", vec2_json(in_robot)},
          {"radius_m", radius_m},
          {"distance_m", range.distance_m},
          {"bearing_deg", range.bearing_deg}};
}

// Reads one JSON object, naming `path` (e.g. "markers[3]") in every error.
class Reader {
 public:
  Reader(const json& object, std::string path, const std::string& source)
      : object_(object), path_(std::move(path)), source_(source) {
    require(object_.is_object(), source_, where("") + "expected an object");
  }

  const json& at(const std::string& key) const {
    const auto it = object_.find(key);
    require(it != object_.end(), source_, where(key) + "missing");
    return *it;
  }
  double number(const std::string& key) const {
    const json& v = at(key);
    require(v.is_number(), source_, where(key) + "expected a number");
    return v.get<double>();
  }
  int integer(const std::string& key) const {
    const json& v = at(key);
    require(v.is_number_integer(), source_, where(key) + "expected an integer");
    return v.get<int>();
  }
  bool boolean(const std::string& key) const {
    const json& v = at(key);
    require(v.is_boolean(), source_, where(key) + "expected true or false");
    return v.get<bool>();
  }
  Vec2 vec2(const std::string& key) const {
    const json& v = at(key);
    require(v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number(), source_,
            where(key) + "expected [x, y]");
    return {v[0].get<double>(), v[1].get<double>()};
  }
  std::optional<Vec2> optional_vec2(const std::string& key) const {
    return at(key).is_null() ? std::nullopt : std::optional(vec2(key));
  }
  cv::Vec3b bgr(const std::string& key) const {
    const json& v = at(key);
    const auto channel_ok = [](const json& c) {
      return c.is_number_integer() && c.get<int>() >= 0 && c.get<int>() <= 255;
    };
    require(
        v.is_array() && v.size() == 3 && channel_ok(v[0]) && channel_ok(v[1]) && channel_ok(v[2]),
        source_, where(key) + "expected [b, g, r] in 0..255");
    return {v[0].get<uchar>(), v[1].get<uchar>(), v[2].get<uchar>()};
  }
  Reader object(const std::string& key) const { return {at(key), path_ + "." + key, source_}; }
  const json& array(const std::string& key) const {
    const json& v = at(key);
    require(v.is_array(), source_, where(key) + "expected an array");
    return v;
  }
  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }

 private:
  std::string where(const std::string& key) const {
    return (key.empty() ? path_ : path_ + "." + key) + ": ";
  }

  const json& object_;
  std::string path_;
  const std::string& source_;
};

MslFieldSpec read_field(const Reader& r) {
  MslFieldSpec f;
  f.width_m = r.number("width_m");
  f.length_m = r.number("length_m");
  f.line_width_m = r.number("line_width_m");
  f.center_circle_radius_m = r.number("center_circle_radius_m");
  f.spot_radius_m = r.number("spot_radius_m");
  f.goal_area_width_m = r.number("goal_area_width_m");
  f.goal_area_depth_m = r.number("goal_area_depth_m");
  f.penalty_area_width_m = r.number("penalty_area_width_m");
  f.penalty_area_depth_m = r.number("penalty_area_depth_m");
  f.penalty_spot_distance_m = r.number("penalty_spot_distance_m");
  f.corner_arc_radius_m = r.number("corner_arc_radius_m");
  f.carpet_margin_m = r.number("carpet_margin_m");
  f.carpet_bgr = r.bgr("carpet_bgr");
  f.line_bgr = r.bgr("line_bgr");
  f.floor_bgr = r.bgr("floor_bgr");
  f.carpet_texture_levels = r.integer("carpet_texture_levels");
  return f;
}

OmniRigParams read_rig(const Reader& r) {
  OmniRigParams p;
  p.width = r.integer("width_px");
  p.height = r.integer("height_px");
  p.xi = r.number("xi");
  p.focal_px = r.number("focal_px");
  p.height_m = r.number("height_m");
  p.tilt_deg = r.number("tilt_deg");
  p.tilt_azimuth_deg = r.number("tilt_azimuth_deg");
  p.center_offset_px = r.vec2("center_offset_px");
  p.mirror_radius_px = r.number("mirror_radius_px");
  return p;
}

RobotRange read_range(const Reader& r) {
  return {r.number("distance_m"), r.number("bearing_deg")};
}

OmniMappingTable read_mapping(const Reader& r) {
  OmniMappingTable table{r.number("theta_step_deg"), r.number("radius_step_px"), {}};
  const json& rows = r.array("rows");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const json& row = rows[i];
    const bool ok = row.is_array() && row.size() == 4 && row[0].is_number() && row[1].is_number() &&
                    (row[2].is_number() || row[2].is_null()) &&
                    row[2].is_null() == row[3].is_null();
    require(ok, r.source(),
            r.path() + ".rows[" + std::to_string(i) +
                "]: expected [theta_deg, radius_px, distance_cm, bearing_deg]");
    OmniMappingSample s{row[0].get<double>(), row[1].get<double>(), std::nullopt};
    if (!row[2].is_null()) s.ground = RobotRange{0.01 * row[2].get<double>(), row[3].get<double>()};
    table.samples.push_back(s);
  }
  return table;
}

// Indented objects; an array of scalars on one line, other arrays one element per line.
void append_text(const json& j, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    std::size_t i = 0;
    for (const auto& [key, value] : j.items()) {
      out += pad + json(key).dump() + ": ";
      append_text(value, indent + 2, out);
      out += ++i < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else if (j.is_array() && !j.empty() &&
             std::any_of(j.begin(), j.end(), [](const json& e) { return e.is_structured(); })) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += pad;
      append_text(j[i], indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string omni_truth_json_text(const OmniTruth& truth) {
  std::string text;
  append_text(omni_truth_to_json(truth), 0, text);
  return text + "\n";
}

json omni_truth_to_json(const OmniTruth& t) {
  json doc;
  doc["format"] = kOmniTruthFormat;
  doc["version"] = kOmniTruthVersion;
  doc["image"] = {{"width_px", t.rig.width},
                  {"height_px", t.rig.height},
                  {"center_px", vec2_json(t.image_center_px)}};
  doc["rig"] = {{"width_px", t.rig.width},
                {"height_px", t.rig.height},
                {"xi", t.rig.xi},
                {"focal_px", t.rig.focal_px},
                {"height_m", t.rig.height_m},
                {"tilt_deg", t.rig.tilt_deg},
                {"tilt_azimuth_deg", t.rig.tilt_azimuth_deg},
                {"center_offset_px", vec2_json(t.rig.center_offset_px)},
                {"mirror_radius_px", t.rig.mirror_radius_px}};
  doc["field"] = field_json(t.field);
  doc["robot"] = {{"position_m", vec2_json(t.robot_pose.position)},
                  {"heading_deg", deg_from_rad(t.robot_pose.heading_rad)},
                  {"body_radius_m", t.robot_body_radius_m}};
  doc["effects"] = {{"brightness_gain", t.effects.brightness_gain},
                    {"blur_sigma_px", t.effects.blur_sigma_px},
                    {"noise_sigma", t.effects.noise_sigma},
                    {"noise_seed", t.noise_seed}};
  if (t.ball) {
    const OmniBallTruth& b = *t.ball;
    json ball = placed_json(b.position_in_field, b.position_in_robot, b.radius_m, b.range);
    ball["center_px"] = optional_vec2_json(b.center_px);
    ball["silhouette_centroid_px"] = optional_vec2_json(b.silhouette_centroid_px);
    ball["visible"] = b.visible;
    doc["ball"] = ball;
  } else {
    doc["ball"] = nullptr;
  }
  doc["markers"] = json::array();
  for (const OmniMarkerTruth& m : t.markers) {
    json marker = placed_json(m.position_in_field, m.position_in_robot, m.radius_m, m.range);
    marker["id"] = m.id;
    marker["pixel"] = optional_vec2_json(m.pixel);
    marker["silhouette_centroid_px"] = optional_vec2_json(m.silhouette_centroid_px);
    marker["visible"] = m.visible;
    doc["markers"].push_back(marker);
  }
  json rows = json::array();
  for (const OmniMappingSample& s : t.mapping.samples) {
    rows.push_back(s.ground ? json::array({s.theta_deg, s.radius_px, 100.0 * s.ground->distance_m,
                                           s.ground->bearing_deg})
                            : json::array({s.theta_deg, s.radius_px, nullptr, nullptr}));
  }
  doc["mapping"] = {{"theta_step_deg", t.mapping.theta_step_deg},
                    {"radius_step_px", t.mapping.radius_step_px},
                    {"columns", {"theta_deg", "radius_px", "distance_cm", "bearing_deg"}},
                    {"rows", rows}};
  return doc;
}

OmniTruth omni_truth_from_json(const json& document, const std::string& source) {
  const Reader r(document, "truth", source);
  require(r.at("format") == kOmniTruthFormat, source,
          std::string("truth.format: expected \"") + kOmniTruthFormat + "\"");
  require(r.integer("version") == kOmniTruthVersion, source,
          "truth.version: expected " + std::to_string(kOmniTruthVersion));
  OmniTruth t;
  t.rig = read_rig(r.object("rig"));
  t.image_center_px = r.object("image").vec2("center_px");
  t.field = read_field(r.object("field"));
  const Reader robot = r.object("robot");
  t.robot_pose = {robot.vec2("position_m"), rad_from_deg(robot.number("heading_deg"))};
  t.robot_body_radius_m = robot.number("body_radius_m");
  const Reader effects = r.object("effects");
  t.effects = {effects.number("brightness_gain"), effects.number("blur_sigma_px"),
               effects.number("noise_sigma")};
  const json& seed = effects.at("noise_seed");
  require(seed.is_number_unsigned() || (seed.is_number_integer() && seed.get<long long>() >= 0),
          source, "truth.effects.noise_seed: expected a non-negative integer");
  t.noise_seed = seed.get<std::uint64_t>();
  if (!r.at("ball").is_null()) {
    const Reader b = r.object("ball");
    t.ball = OmniBallTruth{b.vec2("position_in_field_m"), b.vec2("position_in_robot_m"),
                           b.number("radius_m"),          read_range(b),
                           b.optional_vec2("center_px"),  b.optional_vec2("silhouette_centroid_px"),
                           b.boolean("visible")};
  }
  const json& markers = r.array("markers");
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const Reader m(markers[i], "truth.markers[" + std::to_string(i) + "]", source);
    t.markers.push_back({m.integer("id"), m.vec2("position_in_field_m"),
                         m.vec2("position_in_robot_m"), m.number("radius_m"), read_range(m),
                         m.optional_vec2("pixel"), m.optional_vec2("silhouette_centroid_px"),
                         m.boolean("visible")});
  }
  t.mapping = read_mapping(r.object("mapping"));
  return t;
}

}  // namespace ballsight::sim
