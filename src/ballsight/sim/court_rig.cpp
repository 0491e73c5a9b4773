#include "ballsight/sim/court_rig.hpp"

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/seeding.hpp"

namespace ballsight::sim {
namespace {

/// Focal length that puts the horizontal half field of view at the image edge, through the
/// radial distortion: fx * r_d(tan(hfov / 2)) = width / 2.
double focal_for_hfov(double hfov_rad, int width, const Distortion::Coefficients& d) {
  const double r = std::tan(hfov_rad / 2.0), r2 = r * r;
  const double radial = 1.0 + r2 * (d[0] + r2 * (d[1] + r2 * d[4]));
  return (width / 2.0) / (r * radial);
}

/// Viewing direction (unit, field frame) from `eye` that centres the court's outline in an
/// undistorted image: start at the court centre, then turn towards the centre of the outline's
/// bounding box in normalised coordinates until it stops moving.
Vec3 court_centred_direction(const Vec3& eye, const TennisCourtSpec& court) {
  const GroundRect r = court.court_rect();
  std::vector<Vec3> outline;
  for (const double fx : {0.0, 0.5, 1.0}) {
    for (const double fy : {0.0, 0.5, 1.0}) {
      outline.emplace_back(r.x_min + fx * (r.x_max - r.x_min), r.y_min + fy * (r.y_max - r.y_min),
                           0.0);
    }
  }
  Vec3 direction = (Vec3::Zero() - eye).normalized();
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Rigid3 camera_from_field = camera_from_field_looking_at(eye, eye + direction, 0.0);
    Eigen::AlignedBox2d box;
    for (const Vec3& p : outline) {
      const Vec3 c = camera_from_field * p;
      box.extend(Vec2(c.x() / c.z(), c.y() / c.z()));
    }
    const Vec2 m = box.center();
    direction = camera_from_field.rotation.transpose() * Vec3(m.x(), m.y(), 1.0).normalized();
  }
  return direction;
}

}  // namespace

void CourtRigOptions::validate() const {
  require(width >= 32 && width <= 8192, "width", "must be in [32, 8192] px");
  require(height >= 32 && height <= 8192, "height", "must be in [32, 8192] px");
  require(std::isfinite(hfov_deg) && hfov_deg >= 40.0 && hfov_deg <= 110.0, "hfov_deg",
          "must be in [40, 110] degrees");
  require(std::isfinite(pole_height_min_m) && pole_height_min_m >= 0.2, "pole_height_min_m",
          "must be at least 0.2 m");
  require(std::isfinite(pole_height_max_m) && pole_height_max_m >= pole_height_min_m &&
              pole_height_max_m <= 30.0,
          "pole_height_max_m", "must be in [pole_height_min_m, 30] m");
}

Rigid3 camera_from_field_looking_at(const Vec3& eye, const Vec3& target, double roll_rad) {
  const Vec3 forward = (target - eye).normalized();
  const Vec3 right = forward.cross(Vec3::UnitZ()).normalized();
  const Vec3 down = forward.cross(right);
  Mat3 field_from_camera;
  field_from_camera << right, down, forward;
  const Mat3 rolled = field_from_camera * Eigen::AngleAxisd(roll_rad, Vec3::UnitZ());
  return Rigid3{rolled, eye}.inverse();
}

CourtRig make_court_rig(const TennisCourtSpec& court, const CourtRigOptions& options,
                        std::uint64_t seed) {
  court.validate();
  options.validate();
  std::mt19937_64 rng(seed);
  CourtRig rig{court, {}};
  const double corner_x = court.surround_length_m / 2.0 + 0.25;
  const double corner_y = court.surround_width_m / 2.0 + 0.25;
  const std::array<std::pair<double, double>, kCourtRigCameras> corners = {
      {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}}};
  for (const auto& [sx, sy] : corners) {
    PinholeParams p;
    p.width = options.width;
    p.height = options.height;
    // k3 = 0: with k2 > 9 k1^2 / 20 the radial map is then monotonic over the whole image.
    const double k1 = uniform(rng, -0.35, -0.25), k2 = uniform(rng, 0.08, 0.12);
    p.distortion = {k1, k2, uniform(rng, -1e-3, 1e-3), uniform(rng, -1e-3, 1e-3), 0, 0, 0, 0};
    p.fx = focal_for_hfov(rad_from_deg(options.hfov_deg), options.width, p.distortion) *
           uniform(rng, 0.98, 1.02);
    p.fy = p.fx * uniform(rng, 0.997, 1.003);
    p.cx = (options.width - 1) / 2.0 + uniform(rng, -0.01, 0.01) * options.width;
    p.cy = (options.height - 1) / 2.0 + uniform(rng, -0.01, 0.01) * options.height;

    const Vec3 eye(sx * corner_x + uniform(rng, -0.25, 0.25),
                   sy * corner_y + uniform(rng, -0.25, 0.25),
                   uniform(rng, options.pole_height_min_m, options.pole_height_max_m));
    const Vec3 target = eye + court_centred_direction(eye, court) +
                        0.03 * Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    rig.cameras.push_back({PinholeCamera(p), camera_from_field_looking_at(
                                                 eye, target, rad_from_deg(uniform(rng, -2, 2)))});
  }
  return rig;
}

}  // namespace ballsight::sim
