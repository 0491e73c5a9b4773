#include "ballsight/sim/court_truth_json.hpp"

#include "ballsight/sim/json_io.hpp"
#include "ballsight/sim/tennis_net.hpp"

namespace ballsight::sim {
namespace {

Json net_json(const TennisCourtSpec& c) {
  const std::optional<TennisNet> net = TennisNet::of(c);
  if (!net) return nullptr;
  Json posts = Json::array();
  for (const Vec2& p : net->post_positions()) posts.push_back(json_vec2(p));
  return {{"post_positions_m", posts},
          {"post_radius_m", c.net.post_radius_m},
          {"post_height_m", c.net.post_height_m},
          {"centre_height_m", c.net.centre_height_m},
          {"band_depth_m", c.net.band_depth_m}};
}

Json court_json(const TennisCourtSpec& c) {
  return {{"length_m", c.length_m},
          {"doubles_width_m", c.doubles_width_m},
          {"singles_width_m", c.singles_width_m},
          {"service_line_from_net_m", c.service_line_from_net_m},
          {"line_width_m", c.line_width_m},
          {"surround_length_m", c.surround_length_m},
          {"surround_width_m", c.surround_width_m},
          {"net", net_json(c)}};
}

Json lighting_json(const Lighting& l, const ImageEffects& e) {
  Json shadow = nullptr;
  if (l.shadow) {
    shadow = {{"point_in_field_m", json_vec2(l.shadow->point_in_field)},
              {"direction", json_vec2(l.shadow->direction)},
              {"width_m", l.shadow->width_m},
              {"soft_edge_m", l.shadow->soft_edge_m}};
  }
  return {{"condition", light_condition_name(l.condition)},
          {"to_sun", json_vec3(l.to_sun)},
          {"ambient", l.ambient},
          {"shadow_band", shadow},
          {"brightness_gain", e.brightness_gain},
          {"blur_sigma_px", e.blur_sigma_px},
          {"noise_sigma", e.noise_sigma},
          {"channel_gain_bgr", {e.channel_gain[0], e.channel_gain[1], e.channel_gain[2]}}};
}

Json leaves_json(const std::vector<FloorLeaf>& leaves) {
  Json out = Json::array();
  for (const FloorLeaf& leaf : leaves)
    out.push_back({{"center_m", json_vec2(leaf.center_in_field)},
                   {"axis", json_vec2(leaf.axis)},
                   {"half_length_m", leaf.half_length_m},
                   {"half_width_m", leaf.half_width_m},
                   {"bgr", {leaf.bgr[0], leaf.bgr[1], leaf.bgr[2]}}});
  return out;
}

Json bottles_json(const std::vector<FloorBottle>& bottles) {
  Json out = Json::array();
  for (const FloorBottle& bottle : bottles)
    out.push_back({{"center_m", json_vec2(bottle.center_in_field)},
                   {"radius_m", bottle.radius_m},
                   {"height_m", bottle.height_m},
                   {"bgr", {bottle.bgr[0], bottle.bgr[1], bottle.bgr[2]}}});
  return out;
}

Json obstacles_json(const std::vector<CourtObstacle>& obstacles) {
  Json out = Json::array();
  for (const CourtObstacle& o : obstacles) {
    Json j = {{"kind", obstacle_kind_name(o.kind)},
              {"position_m", json_vec2(o.pose.position)},
              {"heading_rad", o.pose.heading_rad},
              {"half_size_m", json_vec2(o.half_size)},
              {"height_m", o.height_m},
              {"bgr", {o.bgr[0], o.bgr[1], o.bgr[2]}}};
    if (o.walk_to) j["walk_to_m"] = json_vec2(*o.walk_to);
    out.push_back(j);
  }
  return out;
}

Json robot_json(const RobotBox& r) {
  return {{"position_m", json_vec2(r.pose.position)},
          {"heading_rad", r.pose.heading_rad},
          {"length_m", r.length_m},
          {"width_m", r.width_m},
          {"height_m", r.height_m},
          {"front_marker_position_m", json_vec3(r.front_marker().center_in_field)},
          {"back_marker_position_m", json_vec3(r.back_marker().center_in_field)}};
}

Json object_json(const SphereTruth& t) {
  Json views = Json::array();
  for (size_t c = 0; c < t.views.size(); ++c) {
    const SphereViewTruth& v = t.views[c];
    views.push_back({{"camera", c},
                     {"center_px", json_optional_vec2(v.center_px)},
                     {"silhouette_centroid_px", json_optional_vec2(v.silhouette_centroid_px)},
                     {"in_image", v.in_image},
                     {"visible_fraction", v.visible_fraction},
                     {"visible", v.visible},
                     {"hidden_by_net", v.hidden_by_net}});
  }
  return {{"kind", object_kind_name(t.sphere.kind)},
          {"id", t.sphere.id},
          {"position_m", json_vec3(t.sphere.center_in_field)},
          {"radius_m", t.sphere.radius_m},
          {"bgr", {t.sphere.bgr[0], t.sphere.bgr[1], t.sphere.bgr[2]}},
          {"views", views}};
}

}  // namespace

Json rigid3_json(const Rigid3& transform) {
  Json rotation = Json::array();
  for (int r = 0; r < 3; ++r) rotation.push_back(json_vec3(Vec3(transform.rotation.row(r))));
  return {{"rvec", json_vec3(transform.rvec())},
          {"tvec", json_vec3(transform.translation)},
          {"rotation", rotation}};
}

Json intrinsics_json(const PinholeCamera& camera) {
  const PinholeParams& p = camera.params();
  return {{"width", p.width}, {"height", p.height},        {"fx", p.fx}, {"fy", p.fy}, {"cx", p.cx},
          {"cy", p.cy},       {"distortion", p.distortion}};
}

Json court_scene_json(const CourtRig& rig, const CourtScene& scene,
                      const std::vector<SphereTruth>& truth,
                      const std::vector<std::string>& image_files, std::uint64_t seed,
                      int scene_index) {
  Json cameras = Json::array();
  for (size_t i = 0; i < rig.cameras.size(); ++i) {
    const CourtCamera& c = rig.cameras[i];
    Json camera = {{"index", i}, {"image", image_files.at(i)}};
    camera.update(intrinsics_json(c.camera));
    camera["camera_from_field"] = rigid3_json(c.camera_from_field);
    camera["field_from_camera"] = rigid3_json(c.camera_from_field.inverse());
    camera["center_in_field_m"] = json_vec3(c.center_in_field());
    cameras.push_back(camera);
  }
  Json objects = Json::array();
  for (const SphereTruth& t : truth) objects.push_back(object_json(t));
  return {{"format", "ballsight.sim.court"},
          {"version", kCourtTruthVersion},
          {"seed", seed},
          {"scene", scene_index},
          {"court", court_json(rig.court)},
          {"cameras", cameras},
          {"lighting", lighting_json(scene.lighting, scene.effects)},
          {"leaves", leaves_json(scene.leaves)},
          {"bottles", bottles_json(scene.bottles)},
          {"obstacles", obstacles_json(scene.obstacles)},
          {"robot", robot_json(scene.robot)},
          {"objects", objects}};
}

Json chessboard_camera_json(const PinholeCamera& camera, int camera_index,
                            const std::vector<ChessboardViewTruth>& views) {
  Json out = {{"index", camera_index}};
  out.update(intrinsics_json(camera));
  Json list = Json::array();
  for (const ChessboardViewTruth& v : views) {
    Json corners = Json::array();
    for (const Vec2& p : v.corners_px) corners.push_back(json_vec2(p));
    list.push_back({{"image", v.image_file},
                    {"camera_from_board", rigid3_json(v.camera_from_board)},
                    {"corners_px", corners}});
  }
  out["views"] = list;
  return out;
}

Json chessboard_session_json(const ChessboardSpec& board, std::uint64_t seed,
                             const std::vector<Json>& cameras) {
  return {{"format", "ballsight.sim.chessboards"},
          {"version", kCourtTruthVersion},
          {"seed", seed},
          {"board",
           {{"inner_cols", board.inner_cols},
            {"inner_rows", board.inner_rows},
            {"square_m", board.square_m},
            {"border_m", board.border_m}}},
          {"cameras", cameras}};
}

}  // namespace ballsight::sim
