#include "ballsight/camera/omni_rig.hpp"

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {

void OmniRigParams::validate() const {
  const std::string where = "omni rig";
  require(width >= 64 && height >= 64 && width <= 8192 && height <= 8192, where,
          "image size must be between 64 and 8192 px");
  require(std::isfinite(xi) && xi >= 0.0 && xi <= 2.0, where, "xi must be in [0, 2]");
  require(std::isfinite(focal_px) && focal_px > 0.0, where, "focal_px must be positive");
  require(std::isfinite(height_m) && height_m >= 0.1 && height_m <= 3.0, where,
          "height_m must be in [0.1, 3] m");
  require(std::isfinite(tilt_deg) && tilt_deg >= 0.0 && tilt_deg <= 10.0, where,
          "tilt_deg must be in [0, 10] degrees");
  require(std::isfinite(tilt_azimuth_deg), where, "tilt_azimuth_deg must be finite");
  require(center_offset_px.allFinite() && center_offset_px.norm() <= 50.0, where,
          "center_offset_px must be at most 50 px");
  require(std::isfinite(mirror_radius_px) && mirror_radius_px > 10.0, where,
          "mirror_radius_px must be > 10 px");
  mirror.validate();
}

namespace {

UnifiedParams camera_params(const OmniRigParams& p) {
  p.validate();
  UnifiedParams c;
  c.width = p.width;
  c.height = p.height;
  c.xi = p.xi;
  c.fx = c.fy = p.focal_px;
  c.cx = 0.5 * (p.width - 1) + p.center_offset_px.x();
  c.cy = 0.5 * (p.height - 1) + p.center_offset_px.y();
  return c;
}

// Tilting the axis towards robot bearing `azimuth` rotates about the horizontal axis
// perpendicular to it.
Mat3 tilt_rotation(const OmniRigParams& p) {
  const double azimuth = rad_from_deg(p.tilt_azimuth_deg);
  const Vec3 axis(-std::sin(azimuth), std::cos(azimuth), 0.0);
  return Eigen::AngleAxisd(-rad_from_deg(p.tilt_deg), axis).toRotationMatrix();
}

Rigid3 mount(const OmniRigParams& p) {
  // Camera axes in the robot frame for a perfectly aligned rig: image right is the robot's
  // right (-y), image down is backwards (-x), the optical axis points at the floor (-z). So the
  // top of the image is the robot's forward direction, as in the omnivision paper.
  Mat3 aligned;
  aligned << 0, -1, 0, -1, 0, 0, 0, 0, -1;
  return {tilt_rotation(p) * aligned, Vec3(0.0, 0.0, p.height_m)};
}

std::optional<MirrorTracer> tracer(const OmniRigParams& p) {
  if (p.mirror.kind == MirrorKind::kUnified) return std::nullopt;
  return MirrorTracer(p.mirror, MirrorTracer::focal_for_rim(p.mirror, p.mirror_radius_px),
                      Vec2(0.5 * (p.width - 1), 0.5 * (p.height - 1)) + p.center_offset_px);
}

}  // namespace

OmniRigParams with_mirror(OmniRigParams params, MirrorKind kind) {
  params.mirror = default_mirror(kind);
  if (kind != MirrorKind::kUnified) params.height_m = 0.9;
  return params;
}

OmniRig::OmniRig(const OmniRigParams& params)
    : params_(params),
      camera_(camera_params(params)),
      robot_from_camera_(mount(params)),
      tracer_(tracer(params)),
      robot_from_mirror_{tilt_rotation(params), Vec3(0.0, 0.0, params.height_m)} {}

Vec2 OmniRig::principal_point() const {
  return {camera_.params().cx, camera_.params().cy};
}

std::optional<TracedRay> OmniRig::viewing_ray(const Vec2& pixel) const {
  if ((pixel - principal_point()).norm() > params_.mirror_radius_px) return std::nullopt;
  if (tracer_) {
    const std::optional<TracedRay> ray = tracer_->trace(pixel);
    if (!ray) return std::nullopt;
    return TracedRay{robot_from_mirror_ * ray->origin,
                     robot_from_mirror_.rotation * ray->direction};
  }
  const std::optional<Vec3> ray = camera_.unproject(pixel);
  if (!ray) return std::nullopt;
  return TracedRay{robot_from_camera_.translation, robot_from_camera_.rotation * *ray};
}

Vec3 OmniRig::viewpoint_towards(const Vec3& p_in_robot) const {
  if (tracer_) {
    if (const std::optional<Vec2> pixel = project(p_in_robot)) {
      if (const std::optional<TracedRay> ray = tracer_->trace(*pixel)) {
        return robot_from_mirror_ * ray->origin;
      }
    }
  }
  return robot_from_camera_.translation;
}

std::optional<Vec2> OmniRig::project(const Vec3& p_in_robot) const {
  if (tracer_) return tracer_->project(robot_from_mirror_.inverse() * p_in_robot);
  return camera_.project(robot_from_camera_.inverse() * p_in_robot);
}

std::optional<Vec2> OmniRig::ground_from_pixel(const Vec2& pixel) const {
  const std::optional<TracedRay> ray = viewing_ray(pixel);
  if (!ray || ray->direction.z() > -1e-9) return std::nullopt;
  return (ray->origin + (-ray->origin.z() / ray->direction.z()) * ray->direction).head<2>();
}

std::optional<Vec2> OmniRig::pixel_from_point(const Vec3& p_in_robot) const {
  const std::optional<Vec2> pixel = project(p_in_robot);
  if (!pixel || (*pixel - principal_point()).norm() > params_.mirror_radius_px) return std::nullopt;
  return pixel;
}

}  // namespace ballsight
