#include "ballsight/sim/omni_truth.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/raycast.hpp"
#include "ballsight/sim/silhouette.hpp"

namespace ballsight::sim {

namespace {

constexpr int kOutlineSamples = 256;  // polygon centroid error ~1e-4 px for a 100 px blob

struct ImagedOutline {
  std::optional<Vec2> centroid_px;
  bool inside_mirror = false;
};

ImagedOutline image_outline(const OmniRig& rig, const std::vector<Vec3>& outline) {
  const std::optional<std::vector<Vec2>> pixels = project_outline(rig, outline);
  if (!pixels || outline.empty() || !inside_mirror(rig, *pixels)) return {};
  return {polygon_centroid(*pixels), true};
}

OmniBallTruth ball_truth(const OmniScene& scene, const OmniRig& rig) {
  OmniBallTruth t;
  t.position_in_field = scene.ball->position_in_field;
  t.position_in_robot = robot_from_field_point(scene.robot_pose, t.position_in_field);
  t.radius_m = scene.ball->radius_m;
  t.range = robot_range(t.position_in_robot);
  const Vec3 center(t.position_in_robot.x(), t.position_in_robot.y(), t.radius_m);
  t.center_px = rig.pixel_from_point(center);
  const ImagedOutline outline = image_outline(
      rig, sphere_silhouette(rig.viewpoint_towards(center), center, t.radius_m, kOutlineSamples));
  t.visible = outline.inside_mirror && t.center_px.has_value();
  if (t.visible) t.silhouette_centroid_px = outline.centroid_px;
  return t;
}

// True when the ball hides part of the floor disc from the camera's viewpoint: some ray to a
// point of the disc (its centre and five concentric rims) meets the ball first.
bool hidden_by_ball(const OmniScene& scene, const OmniRig& rig, const Vec2& disc_in_robot,
                    double disc_radius) {
  if (!scene.ball) return false;
  const Vec2 ball_in_robot =
      robot_from_field_point(scene.robot_pose, scene.ball->position_in_field);
  const Vec3 ball_center(ball_in_robot.x(), ball_in_robot.y(), scene.ball->radius_m);
  const Vec3 viewpoint = rig.viewpoint_towards({disc_in_robot.x(), disc_in_robot.y(), 0.0});
  std::vector<Vec3> points{{disc_in_robot.x(), disc_in_robot.y(), 0.0}};
  for (int ring = 1; ring <= 5; ++ring) {
    const std::vector<Vec3> rim = floor_disc_rim(disc_in_robot, disc_radius * ring / 5.0, 64);
    points.insert(points.end(), rim.begin(), rim.end());
  }
  for (const Vec3& p : points) {
    const Vec3 to_point = p - viewpoint;
    const std::optional<double> t =
        intersect_sphere(viewpoint, to_point.normalized(), ball_center, scene.ball->radius_m);
    if (t && *t < to_point.norm()) return true;
  }
  return false;
}

OmniMarkerTruth marker_truth(const OmniScene& scene, const OmniRig& rig, const FloorMarker& m) {
  OmniMarkerTruth t;
  t.id = m.id;
  t.position_in_field = m.position_in_field;
  t.position_in_robot = robot_from_field_point(scene.robot_pose, m.position_in_field);
  t.radius_m = m.radius_m;
  t.range = robot_range(t.position_in_robot);
  t.pixel = rig.pixel_from_point({t.position_in_robot.x(), t.position_in_robot.y(), 0.0});
  const ImagedOutline outline =
      image_outline(rig, floor_disc_rim(t.position_in_robot, m.radius_m, kOutlineSamples));
  t.silhouette_centroid_px = outline.centroid_px;
  t.visible = outline.inside_mirror && t.pixel.has_value() &&
              !hidden_by_ball(scene, rig, t.position_in_robot, m.radius_m);
  return t;
}

}  // namespace

RobotRange robot_range(const Vec2& p_in_robot) {
  return {p_in_robot.norm(),
          wrap_deg_180(deg_from_rad(std::atan2(p_in_robot.y(), p_in_robot.x())))};
}

OmniMappingTable sample_omni_mapping(const OmniRig& rig, double theta_step_deg,
                                     double radius_step_px) {
  require(std::isfinite(theta_step_deg) && theta_step_deg > 0.0 && theta_step_deg <= 360.0,
          "mapping table", "theta_step_deg must be in (0, 360]");
  require(std::isfinite(radius_step_px) && radius_step_px >= 0.1, "mapping table",
          "radius_step_px must be at least 0.1 px");
  OmniMappingTable table{theta_step_deg, radius_step_px, {}};
  const double last_radius = rig.params().mirror_radius_px - 1e-6;  // strictly inside
  for (int i = 0; i * theta_step_deg < 360.0 - 1e-9; ++i) {
    const double theta = i * theta_step_deg;
    for (int j = 1; j * radius_step_px < last_radius; ++j) {
      const double r = j * radius_step_px;
      const Vec2 pixel = pixel_from_image_polar({theta, r}, rig.principal_point());
      const std::optional<Vec2> ground = rig.ground_from_pixel(pixel);
      table.samples.push_back(
          {theta, r, ground ? std::optional(robot_range(*ground)) : std::nullopt});
    }
  }
  return table;
}

OmniTruth make_omni_truth(const OmniScene& scene, const OmniRig& rig) {
  OmniTruth truth;
  truth.rig = scene.rig;
  truth.image_center_px = rig.principal_point();
  truth.field = scene.field;
  truth.robot_pose = scene.robot_pose;
  truth.robot_body_radius_m = scene.robot_body_radius_m;
  truth.effects = scene.effects;
  truth.noise_seed = scene.noise_seed;
  if (scene.ball) truth.ball = ball_truth(scene, rig);
  truth.markers.reserve(scene.markers.size());
  for (const FloorMarker& m : scene.markers) truth.markers.push_back(marker_truth(scene, rig, m));
  truth.mapping = sample_omni_mapping(rig);
  return truth;
}

}  // namespace ballsight::sim
