#include "ballsight/sim/omni_renderer.hpp"

#include <algorithm>
#include <cmath>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/sim/raycast.hpp"
#include "ballsight/sim/silhouette.hpp"

namespace ballsight::sim {

namespace {

constexpr int kOutlineSamples = 64;  // enough for a bounding box padded by 2 px

bool same_rig(const OmniRigParams& a, const OmniRigParams& b) {
  return a.width == b.width && a.height == b.height && a.xi == b.xi && a.focal_px == b.focal_px &&
         a.height_m == b.height_m && a.tilt_deg == b.tilt_deg &&
         a.tilt_azimuth_deg == b.tilt_azimuth_deg && a.center_offset_px == b.center_offset_px &&
         a.mirror_radius_px == b.mirror_radius_px && a.mirror == b.mirror;
}

// Objects are sampled on a kGrid x kGrid grid of sub-pixel offsets in (-0.5, 0.5).
constexpr int kGrid = 4;
constexpr int kSamples = kGrid * kGrid;

template <class F>
void for_each_subsample(F&& f) {
  for (int sy = 0; sy < kGrid; ++sy) {
    for (int sx = 0; sx < kGrid; ++sx) f((sx + 0.5) / kGrid - 0.5, (sy + 0.5) / kGrid - 0.5);
  }
}

// Lays `hits` of kSamples samples whose colours sum to `sum` over the pixel.
void blend(cv::Vec3b& pixel, const Vec3& sum, int hits) {
  if (hits == 0) return;
  const int rest = kSamples - hits;
  for (int c = 0; c < 3; ++c) {
    pixel[c] = cv::saturate_cast<uchar>((sum[c] + rest * pixel[c]) / kSamples);
  }
}

// The sun of the scene, high above the field.
Vec3 to_light_in_field() {
  return Vec3(0.3, -0.2, 1.0).normalized();
}

}  // namespace

OmniRenderer::OmniRenderer(const OmniRigParams& rig_params) : rig_(rig_params) {
  const int w = rig_params.width;
  const int h = rig_params.height;
  kind_.assign(static_cast<std::size_t>(w) * h, PixelKind::kOutsideMirror);
  ray_.assign(kind_.size(), Vec3::Zero());
  origin_.assign(kind_.size(), Vec3::Zero());
  floor_.assign(kind_.size(), Vec2::Zero());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const std::optional<TracedRay> ray = rig_.viewing_ray({x, y});
      if (!ray) continue;
      ray_[i] = ray->direction;
      origin_[i] = ray->origin;
      const std::optional<double> t = intersect_horizontal_plane(ray->origin, ray->direction, 0.0);
      if (t) {
        kind_[i] = PixelKind::kFloor;
        floor_[i] = (ray->origin + *t * ray->direction).head<2>();
      } else {
        kind_[i] = PixelKind::kAboveHorizon;
      }
    }
  }
}

cv::Rect OmniRenderer::image_box(const std::vector<Vec3>& outline_in_robot) const {
  const cv::Rect image(0, 0, rig_.params().width, rig_.params().height);
  const std::optional<std::vector<Vec2>> pixels = project_outline(rig_, outline_in_robot);
  if (!pixels || pixels->empty()) return image;  // cannot bound it: cast every pixel
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const Vec2& p : *pixels) {
    x0 = std::min(x0, p.x());
    y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x());
    y1 = std::max(y1, p.y());
  }
  constexpr double kPad = 2.0;  // covers the polygon's chords and pixel rounding
  const double lo_x = std::clamp(std::floor(x0 - kPad), -1.0, image.width + 1.0);
  const double lo_y = std::clamp(std::floor(y0 - kPad), -1.0, image.height + 1.0);
  const double hi_x = std::clamp(std::ceil(x1 + kPad), -1.0, image.width + 1.0);
  const double hi_y = std::clamp(std::ceil(y1 + kPad), -1.0, image.height + 1.0);
  const cv::Rect box(static_cast<int>(lo_x), static_cast<int>(lo_y),
                     static_cast<int>(hi_x - lo_x) + 1, static_cast<int>(hi_y - lo_y) + 1);
  return box & image;
}

void OmniRenderer::shade_floor(const OmniScene& scene, const MslField& field, cv::Mat& bgr) const {
  const Rigid2 field_from_robot = scene.robot_pose.field_from_robot();
  const Eigen::Matrix2d rotation = field_from_robot.rotation();
  const double body2 = scene.robot_body_radius_m * scene.robot_body_radius_m;
  const int w = bgr.cols;
  for (int y = 0; y < bgr.rows; ++y) {
    auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      switch (kind_[i]) {
        case PixelKind::kOutsideMirror:
          row[x] = cv::Vec3b(0, 0, 0);
          break;
        case PixelKind::kAboveHorizon:
          row[x] = scene.palette.background_bgr;
          break;
        case PixelKind::kFloor: {
          const Vec2& p_in_robot = floor_[i];
          row[x] = p_in_robot.squaredNorm() < body2
                       ? scene.palette.robot_body_bgr
                       : field.colour_at(rotation * p_in_robot + field_from_robot.translation);
          break;
        }
      }
    }
  }
}

template <class V>
OmniRenderer::Local<V> OmniRenderer::local(const std::vector<V>& values, int x, int y,
                                           PixelKind least) const {
  const int w = rig_.params().width;
  const int h = rig_.params().height;
  const auto usable = [&](int u, int v) {
    return u >= 0 && v >= 0 && u < w && v < h &&
           kind_[static_cast<std::size_t>(v) * w + u] >= least;
  };
  const auto value = [&](int u, int v) { return values[static_cast<std::size_t>(v) * w + u]; };
  // Central difference where both neighbours exist, one-sided at an edge, flat without any.
  const auto derivative = [&](int ux, int uy) -> V {
    const bool ahead = usable(x + ux, y + uy);
    const bool behind = usable(x - ux, y - uy);
    if (ahead && behind) return 0.5 * (value(x + ux, y + uy) - value(x - ux, y - uy));
    if (ahead) return value(x + ux, y + uy) - value(x, y);
    if (behind) return value(x, y) - value(x - ux, y - uy);
    return V::Zero();
  };
  return {value(x, y), derivative(1, 0), derivative(0, 1)};
}

void OmniRenderer::draw_marker(const OmniScene& scene, const FloorMarker& marker,
                               cv::Mat& bgr) const {
  const Vec2 center = robot_from_field_point(scene.robot_pose, marker.position_in_field);
  const double radius = marker.radius_m;
  const cv::Rect box = image_box(floor_disc_rim(center, radius, kOutlineSamples));
  const cv::Vec3b& colour = scene.palette.marker_bgr;
  for (int y = box.y; y < box.y + box.height; ++y) {
    auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = box.x; x < box.x + box.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * bgr.cols + x;
      if (kind_[i] != PixelKind::kFloor) continue;
      const Local<Vec2> floor = local(floor_, x, y, PixelKind::kFloor);
      const double reach = 0.5 * (floor.d_dx.norm() + floor.d_dy.norm());  // pixel's half size
      const double distance = (floor.value - center).norm();
      if (distance > radius + reach) continue;
      int hits = 0;
      if (distance < radius - reach) {
        hits = kSamples;
      } else {
        for_each_subsample([&](double dx, double dy) {
          hits += (floor.at(dx, dy) - center).squaredNorm() <= radius * radius ? 1 : 0;
        });
      }
      const Vec3 sum = hits * Vec3(colour[0], colour[1], colour[2]);
      blend(row[x], sum, hits);
    }
  }
}

void OmniRenderer::draw_ball(const OmniScene& scene, cv::Mat& bgr) const {
  const OmniBall& ball = *scene.ball;
  const Vec2 ground = robot_from_field_point(scene.robot_pose, ball.position_in_field);
  const Vec3 center(ground.x(), ground.y(), ball.radius_m);
  const Mat3 robot_from_field =
      Eigen::AngleAxisd(-scene.robot_pose.heading_rad, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 to_light = robot_from_field * to_light_in_field();
  const cv::Rect box = image_box(
      sphere_silhouette(rig_.viewpoint_towards(center), center, ball.radius_m, kOutlineSamples));
  for (int y = box.y; y < box.y + box.height; ++y) {
    auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = box.x; x < box.x + box.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * bgr.cols + x;
      if (kind_[i] == PixelKind::kOutsideMirror) continue;
      const Local<Vec3> ray = local(ray_, x, y, PixelKind::kAboveHorizon);
      const Local<Vec3> origin = local(origin_, x, y, PixelKind::kAboveHorizon);
      int hits = 0;
      Vec3 sum = Vec3::Zero();
      for_each_subsample([&](double dx, double dy) {
        const Vec3 direction = ray.at(dx, dy).normalized();
        const Vec3 from = origin.at(dx, dy);
        const std::optional<double> t = intersect_sphere(from, direction, center, ball.radius_m);
        if (!t) return;
        const Vec3 normal = (from + *t * direction - center) / ball.radius_m;
        const cv::Vec3b c = shade(scene.palette.ball_bgr, normal, to_light);
        sum += Vec3(c[0], c[1], c[2]);
        ++hits;
      });
      blend(row[x], sum, hits);
    }
  }
}

OmniFrame OmniRenderer::render(const OmniScene& scene) const {
  scene.validate();
  require(same_rig(scene.rig, rig_.params()), "scene.rig",
          "differs from the rig this renderer was built for");
  const MslField field(scene.field);
  OmniFrame frame;
  frame.bgr.create(rig_.params().height, rig_.params().width, CV_8UC3);
  shade_floor(scene, field, frame.bgr);
  for (const FloorMarker& marker : scene.markers) draw_marker(scene, marker, frame.bgr);
  if (scene.ball) draw_ball(scene, frame.bgr);
  apply_image_effects(frame.bgr, scene.effects, scene.noise_seed);
  frame.truth = make_omni_truth(scene, rig_);
  return frame;
}

OmniFrame render_omni_scene(const OmniScene& scene) {
  return OmniRenderer(scene.rig).render(scene);
}

}  // namespace ballsight::sim
