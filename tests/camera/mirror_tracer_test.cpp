#include "ballsight/camera/mirror_tracer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr MirrorKind kTraced[] = {MirrorKind::kSphere, MirrorKind::kCone, MirrorKind::kTable};

// Where a traced ray meets the floor `h` below the camera.
std::optional<Vec3> floor_hit(const TracedRay& ray, double h) {
  if (ray.direction.z() >= 0.0) return std::nullopt;
  return ray.origin + ((-h - ray.origin.z()) / ray.direction.z()) * ray.direction;
}

// Property: projecting the floor point a pixel's traced ray meets gives the pixel back, over the
// mirror image where the floor distance still grows outwards, with lens distortion and a ripple.
TEST(MirrorTracer, ProjectionInvertsTheTrace) {
  for (const MirrorKind kind : kTraced) {
    SCOPED_TRACE(std::string(mirror_kind_name(kind)));
    MirrorProfile profile = default_mirror(kind);
    profile.lens_k1 = -0.05;
    // A cone reflects at one slope, so a ripple's slope folds its image (some floor points are
    // seen twice): rippled here are the curved mirrors only.
    if (kind != MirrorKind::kCone) profile.ripple_amplitude_m = 2e-6;
    const Vec2 principal(321.0, 238.0);
    const MirrorTracer tracer(profile, MirrorTracer::focal_for_rim(profile, 230.0), principal);
    int checked = 0;
    for (double theta = 3.0; theta < 360.0; theta += 17.0) {
      double farthest = 0.0;  // beyond a fold (the cone's rim) a floor point is imaged twice
      for (double r = 30.0; r < 230.0; r += 11.0) {
        const Vec2 pixel = principal + r * Vec2(std::cos(theta), std::sin(theta));
        const auto ray = tracer.trace(pixel);
        ASSERT_TRUE(ray) << r;
        const auto hit = floor_hit(*ray, 0.6);
        if (!hit || hit->head<2>().norm() > 8.0 || hit->head<2>().norm() <= farthest) continue;
        farthest = hit->head<2>().norm();
        const auto back = tracer.project(*hit);
        ASSERT_TRUE(back) << r << " px";
        EXPECT_LT((*back - pixel).norm(), 1e-6) << r << " px";
        ++checked;
      }
    }
    EXPECT_GT(checked, 100);
  }
}

// The reflection obeys the law of reflection: incoming and outgoing make equal angles with the
// normal, and the rim images at the radius the focal length was chosen for.
TEST(MirrorTracer, ReflectsLikeAMirrorAndFillsTheRim) {
  const MirrorProfile sphere = default_mirror(MirrorKind::kSphere);
  const MirrorTracer tracer(sphere, MirrorTracer::focal_for_rim(sphere, 240.0), Vec2::Zero());
  const auto ray = tracer.trace({0.0, -120.0});
  ASSERT_TRUE(ray);
  const Vec3 in = ray->origin.normalized();
  const Vec3 centre(0.0, 0.0, sphere.apex_above_camera_m + sphere.sphere_radius_m);
  const Vec3 normal = (ray->origin - centre).normalized();
  EXPECT_NEAR(std::abs(in.dot(normal)), std::abs(ray->direction.dot(normal)), 1e-9);
  EXPECT_NEAR(ray->origin.x() / std::hypot(ray->origin.x(), ray->origin.y()), 1.0, 1e-9);
  EXPECT_TRUE(tracer.trace({0.0, -239.0}));
  EXPECT_FALSE(tracer.trace({0.0, -241.0}));
}

TEST(MirrorTracer, ARigWithATracedMirrorMapsPixelsToTheFloorAndBack) {
  OmniRigParams params;
  params.mirror = default_mirror(MirrorKind::kTable);
  params.tilt_deg = 1.5;
  params.tilt_azimuth_deg = 40.0;
  params.center_offset_px = {4.0, -2.0};
  const OmniRig rig(params);
  for (const Vec2& floor : {Vec2(1.2, 0.3), Vec2(-0.8, 2.0), Vec2(0.1, -3.0)}) {
    const auto pixel = rig.pixel_from_point({floor.x(), floor.y(), 0.0});
    ASSERT_TRUE(pixel);
    const auto back = rig.ground_from_pixel(*pixel);
    ASSERT_TRUE(back);
    EXPECT_LT((*back - floor).norm(), 1e-6);
  }
  EXPECT_GT(rig.viewpoint_height_m(), params.height_m + params.mirror.apex_above_camera_m);
}

TEST(MirrorTracer, BadProfilesNameTheField) {
  MirrorProfile p = default_mirror(MirrorKind::kSphere);
  p.sphere_radius_m = 0.01;
  EXPECT_THROW(p.validate(), InputError);
  p = default_mirror(MirrorKind::kTable);
  p.table_m[3].y() = -1.0;
  try {
    p.validate();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mirror.table_m"), std::string::npos) << e.what();
  }
  try {
    parse_mirror_kind("parabolic", "--mirror");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--mirror: unknown mirror 'parabolic'"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace ballsight
