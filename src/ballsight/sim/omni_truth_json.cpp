#include "ballsight/sim/omni_truth_json.hpp"

#include "ballsight/core/angle.hpp"

namespace ballsight::sim {

namespace {

Json field_json(const MslFieldSpec& f) {
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
          {"carpet_bgr", json_bgr(f.carpet_bgr)},
          {"line_bgr", json_bgr(f.line_bgr)},
          {"floor_bgr", json_bgr(f.floor_bgr)},
          {"carpet_texture_levels", f.carpet_texture_levels}};
}

MslFieldSpec read_field(const JsonReader& r) {
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

Json mirror_json(const MirrorProfile& m) {
  Json table = Json::array();
  for (const Vec2& point : m.table_m) table.push_back(json_vec2(point));
  return {{"kind", mirror_kind_name(m.kind)},
          {"rim_radius_m", m.rim_radius_m},
          {"apex_above_camera_m", m.apex_above_camera_m},
          {"sphere_radius_m", m.sphere_radius_m},
          {"cone_half_angle_deg", m.cone_half_angle_deg},
          {"table_m", table},
          {"ripple_amplitude_m", m.ripple_amplitude_m},
          {"ripple_period_m", m.ripple_period_m},
          {"lens_k1", m.lens_k1}};
}

MirrorProfile read_mirror(const JsonReader& r) {
  MirrorProfile m;
  const Json& kind = r.at("kind");
  const std::optional<MirrorKind> known =
      kind.is_string() ? mirror_kind_named(kind.get<std::string>()) : std::nullopt;
  r.require_that(known.has_value(), "kind",
                 "expected \"unified\", \"sphere\", \"cone\" or \"table\"");
  m.kind = *known;
  m.rim_radius_m = r.number("rim_radius_m");
  m.apex_above_camera_m = r.number("apex_above_camera_m");
  m.sphere_radius_m = r.number("sphere_radius_m");
  m.cone_half_angle_deg = r.number("cone_half_angle_deg");
  const Json& table = r.array("table_m");
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Json& point = table[i];
    r.require_that(
        point.is_array() && point.size() == 2 && point[0].is_number() && point[1].is_number(),
        "table_m", "expected [radius, height] pairs");
    m.table_m.push_back({point[0].get<double>(), point[1].get<double>()});
  }
  m.ripple_amplitude_m = r.number("ripple_amplitude_m");
  m.ripple_period_m = r.number("ripple_period_m");
  m.lens_k1 = r.number("lens_k1");
  return m;
}

Json rig_json(const OmniRigParams& p) {
  return {{"width_px", p.width},
          {"height_px", p.height},
          {"xi", p.xi},
          {"focal_px", p.focal_px},
          {"height_m", p.height_m},
          {"tilt_deg", p.tilt_deg},
          {"tilt_azimuth_deg", p.tilt_azimuth_deg},
          {"center_offset_px", json_vec2(p.center_offset_px)},
          {"mirror_radius_px", p.mirror_radius_px},
          {"mirror", mirror_json(p.mirror)}};
}

OmniRigParams read_rig(const JsonReader& r) {
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
  // Truth files before the mirror profiles: the unified model.
  if (r.has("mirror")) p.mirror = read_mirror(r.object("mirror"));
  return p;
}

// The keys a ball and a marker share.
Json placed_json(const Vec2& in_field, const Vec2& in_robot, double radius_m,
                 const RobotRange& range) {
  return {{"position_in_field_m", json_vec2(in_field)},
          {"position_in_robot_m", json_vec2(in_robot)},
          {"radius_m", radius_m},
          {"distance_m", range.distance_m},
          {"bearing_deg", range.bearing_deg}};
}

RobotRange read_range(const JsonReader& r) {
  return {r.number("distance_m"), r.number("bearing_deg")};
}

Json mapping_json(const OmniMappingTable& table) {
  Json rows = Json::array();
  for (const OmniMappingSample& s : table.samples) {
    rows.push_back(s.ground ? Json::array({s.theta_deg, s.radius_px, 100.0 * s.ground->distance_m,
                                           s.ground->bearing_deg})
                            : Json::array({s.theta_deg, s.radius_px, nullptr, nullptr}));
  }
  return {{"theta_step_deg", table.theta_step_deg},
          {"radius_step_px", table.radius_step_px},
          {"columns", {"theta_deg", "radius_px", "distance_cm", "bearing_deg"}},
          {"rows", rows}};
}

OmniMappingTable read_mapping(const JsonReader& r) {
  OmniMappingTable table{r.number("theta_step_deg"), r.number("radius_step_px"), {}};
  const Json& rows = r.array("rows");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Json& row = rows[i];
    const bool ok = row.is_array() && row.size() == 4 && row[0].is_number() && row[1].is_number() &&
                    (row[2].is_number() || row[2].is_null()) &&
                    (row[3].is_number() || row[3].is_null()) &&
                    row[2].is_null() == row[3].is_null();
    r.require_that(ok, "rows[" + std::to_string(i) + "]",
                   "expected [theta_deg, radius_px, distance_cm, bearing_deg]");
    OmniMappingSample s{row[0].get<double>(), row[1].get<double>(), std::nullopt};
    if (!row[2].is_null()) {
      s.ground = RobotRange{0.01 * row[2].get<double>(), row[3].get<double>()};
    }
    table.samples.push_back(s);
  }
  return table;
}

}  // namespace

Json omni_truth_to_json(const OmniTruth& t) {
  Json doc;
  doc["format"] = kOmniTruthFormat;
  doc["version"] = kOmniTruthVersion;
  doc["image"] = {{"width_px", t.rig.width},
                  {"height_px", t.rig.height},
                  {"center_px", json_vec2(t.image_center_px)}};
  doc["rig"] = rig_json(t.rig);
  doc["field"] = field_json(t.field);
  doc["robot"] = {{"position_m", json_vec2(t.robot_pose.position)},
                  {"heading_deg", deg_from_rad(t.robot_pose.heading_rad)},
                  {"body_radius_m", t.robot_body_radius_m}};
  doc["effects"] = {{"brightness_gain", t.effects.brightness_gain},
                    {"blur_sigma_px", t.effects.blur_sigma_px},
                    {"noise_sigma", t.effects.noise_sigma},
                    {"noise_seed", t.noise_seed}};
  doc["ball"] = nullptr;
  if (t.ball) {
    const OmniBallTruth& b = *t.ball;
    Json ball = placed_json(b.position_in_field, b.position_in_robot, b.radius_m, b.range);
    ball["center_px"] = json_optional_vec2(b.center_px);
    ball["silhouette_centroid_px"] = json_optional_vec2(b.silhouette_centroid_px);
    ball["visible"] = b.visible;
    doc["ball"] = ball;
  }
  doc["markers"] = Json::array();
  for (const OmniMarkerTruth& m : t.markers) {
    Json marker{{"id", m.id}};
    marker.update(placed_json(m.position_in_field, m.position_in_robot, m.radius_m, m.range));
    marker["pixel"] = json_optional_vec2(m.pixel);
    marker["silhouette_centroid_px"] = json_optional_vec2(m.silhouette_centroid_px);
    marker["visible"] = m.visible;
    doc["markers"].push_back(marker);
  }
  doc["mapping"] = mapping_json(t.mapping);
  return doc;
}

std::string omni_truth_json_text(const OmniTruth& truth) {
  return json_text(omni_truth_to_json(truth));
}

OmniTruth omni_truth_from_json(const Json& document, const std::string& source) {
  const JsonReader r(document, "truth", source);
  r.require_that(r.at("format") == kOmniTruthFormat, "format",
                 std::string("expected \"") + kOmniTruthFormat + "\"");
  r.require_that(r.integer("version") == kOmniTruthVersion, "version",
                 "expected " + std::to_string(kOmniTruthVersion));
  OmniTruth t;
  t.rig = read_rig(r.object("rig"));
  t.image_center_px = r.object("image").vec2("center_px");
  t.field = read_field(r.object("field"));
  const JsonReader robot = r.object("robot");
  t.robot_pose = {robot.vec2("position_m"), rad_from_deg(robot.number("heading_deg"))};
  t.robot_body_radius_m = robot.number("body_radius_m");
  const JsonReader effects = r.object("effects");
  t.effects = {effects.number("brightness_gain"), effects.number("blur_sigma_px"),
               effects.number("noise_sigma")};
  t.noise_seed = effects.unsigned_integer("noise_seed");
  if (!r.at("ball").is_null()) {
    const JsonReader b = r.object("ball");
    t.ball = OmniBallTruth{b.vec2("position_in_field_m"), b.vec2("position_in_robot_m"),
                           b.number("radius_m"),          read_range(b),
                           b.optional_vec2("center_px"),  b.optional_vec2("silhouette_centroid_px"),
                           b.boolean("visible")};
  }
  const Json& markers = r.array("markers");
  for (std::size_t i = 0; i < markers.size(); ++i) {
    const JsonReader m = r.element(markers, i, "markers");
    t.markers.push_back({m.integer("id"), m.vec2("position_in_field_m"),
                         m.vec2("position_in_robot_m"), m.number("radius_m"), read_range(m),
                         m.optional_vec2("pixel"), m.optional_vec2("silhouette_centroid_px"),
                         m.boolean("visible")});
  }
  t.mapping = read_mapping(r.object("mapping"));
  return t;
}

}  // namespace ballsight::sim
