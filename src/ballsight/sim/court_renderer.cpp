#include "ballsight/sim/court_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ballsight/core/raycast_box.hpp"
#include "ballsight/sim/raycast.hpp"
#include "ballsight/sim/silhouette.hpp"

namespace ballsight::sim {
namespace {

const cv::Vec3f kSkyHorizonBgr{225.0f, 215.0f, 205.0f};
const cv::Vec3f kSkyZenithBgr{215.0f, 160.0f, 110.0f};
constexpr double kHazeDistanceM = 400.0;
constexpr double kMaxAlongFootprintM = 20.0;

/// Pixel rectangle [x0, x1) x [y0, y1) of an object, clipped to the image.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

/// Bounding box of projected points plus a margin, clipped; the whole image when a point fails
/// to project (part of the object is outside the lens model's range).
PixelBox box_around(const std::vector<std::optional<Vec2>>& pixels, const cv::Size& size) {
  constexpr double kMarginPx = 2.0;
  double x_min = INFINITY, y_min = INFINITY, x_max = -INFINITY, y_max = -INFINITY;
  for (const auto& p : pixels) {
    if (!p) return {0, 0, size.width, size.height};
    x_min = std::min(x_min, p->x());
    x_max = std::max(x_max, p->x());
    y_min = std::min(y_min, p->y());
    y_max = std::max(y_max, p->y());
  }
  const auto clip = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
  };
  return {clip(std::floor(x_min - kMarginPx), size.width),
          clip(std::floor(y_min - kMarginPx), size.height),
          clip(std::ceil(x_max + kMarginPx) + 1.0, size.width),
          clip(std::ceil(y_max + kMarginPx) + 1.0, size.height)};
}

PixelBox sphere_box(const CourtCamera& camera, const SceneSphere& sphere, const cv::Size& size) {
  const Vec3 c = camera.camera_from_field * sphere.center_in_field;
  if (c.z() < -sphere.radius_m) return {};  // wholly behind the camera
  const auto rim = sphere_outline_pixels(camera.camera, c, sphere.radius_m, 32);
  if (!rim) return {0, 0, size.width, size.height};
  std::vector<std::optional<Vec2>> pixels(rim->begin(), rim->end());
  return box_around(pixels, size);
}

PixelBox floor_box_box(const CourtCamera& camera, const FloorBox& box, const cv::Size& size) {
  // Points along the 12 edges: straight edges bow under lens distortion.
  constexpr int kPerEdge = 8;
  const Rigid2 field_from_box = box.pose.field_from_robot();
  std::vector<std::optional<Vec2>> pixels;
  const auto corner = [&](int i) {
    const Vec2 xy = field_from_box * Vec2((i & 1 ? 1 : -1) * box.half_size.x(),
                                          (i & 2 ? 1 : -1) * box.half_size.y());
    return Vec3(xy.x(), xy.y(), i & 4 ? box.height : 0.0);
  };
  for (int a = 0; a < 8; ++a) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (a & bit) continue;
      const Vec3 p0 = corner(a), p1 = corner(a | bit);
      for (int k = 0; k <= kPerEdge; ++k) {
        const Vec3 p = p0 + (p1 - p0) * (static_cast<double>(k) / kPerEdge);
        pixels.push_back(camera.camera.project(camera.camera_from_field * p));
      }
    }
  }
  return box_around(pixels, size);
}

cv::Vec3f scaled(const cv::Vec3b& bgr, double k) {
  const auto f = static_cast<float>(k);
  return {bgr[0] * f, bgr[1] * f, bgr[2] * f};
}

}  // namespace

double ObjectCoverage::visible_fraction() const {
  return unoccluded_samples > 0 ? static_cast<double>(visible_samples) / unoccluded_samples : 0.0;
}

CourtRenderer::CourtRenderer(const CourtCamera& camera, const TennisCourtSpec& court)
    : camera_(camera),
      center_in_field_(camera.center_in_field()),
      rays_(camera.camera, camera.camera_from_field.rotation.transpose()) {
  court.validate();
  precompute_floor(court);
}

void CourtRenderer::precompute_floor(const TennisCourtSpec& court) {
  const cv::Size size(rays_.width(), rays_.height());
  floor_albedo_.create(size, CV_32FC3);
  floor_haze_.create(size, CV_32FC3);
  floor_point_ = cv::Mat(size, CV_32FC2, cv::Scalar(0, 0));
  const std::vector<GroundRect> lines = court.line_rects();
  const Vec3& o = center_in_field_;
  for (int y = 0; y < size.height; ++y) {
    auto* albedo_row = floor_albedo_.ptr<cv::Vec3f>(y);
    auto* haze_row = floor_haze_.ptr<cv::Vec3f>(y);
    auto* point_row = floor_point_.ptr<cv::Vec2f>(y);
    for (int x = 0; x < size.width; ++x) {
      const Vec3 d = rays_.at(x, y);
      if (d.z() > -1e-4) {
        const double up = std::clamp(d.z() * 3.0, 0.0, 1.0);
        albedo_row[x] = cv::Vec3f(0.0f, 0.0f, 0.0f);
        haze_row[x] = kSkyHorizonBgr + (kSkyZenithBgr - kSkyHorizonBgr) * static_cast<float>(up);
        continue;
      }
      const double t = -o.z() / d.z();
      const Vec3 p = o + t * d;
      // Footprint of the pixel on the ground: its angular size from the neighbouring ray,
      // stretched along the viewing direction by the grazing angle.
      const Vec3 next = rays_.at(x + 1 < size.width ? x + 1 : x - 1, y);
      const double across = t * (next - d).norm();
      const double along = std::min(across / -d.z(), kMaxAlongFootprintM);
      const Vec2 u = d.head<2>().normalized();
      const Vec2 half(0.5 * (along * std::abs(u.x()) + across * std::abs(u.y())),
                      0.5 * (along * std::abs(u.y()) + across * std::abs(u.x())));
      const auto haze = static_cast<float>(1.0 - std::exp(-t / kHazeDistanceM));
      albedo_row[x] = floor_albedo(court, lines, p.head<2>(), half) * (1.0f - haze);
      haze_row[x] = kSkyHorizonBgr * haze;
      point_row[x] = cv::Vec2f(static_cast<float>(p.x()), static_cast<float>(p.y()));
    }
  }
}

void CourtRenderer::light_floor(const Lighting& lighting, cv::Mat& bgr) const {
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* albedo_row = floor_albedo_.ptr<cv::Vec3f>(y);
    const auto* haze_row = floor_haze_.ptr<cv::Vec3f>(y);
    const auto* point_row = floor_point_.ptr<cv::Vec2f>(y);
    auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const Vec3 p(point_row[x][0], point_row[x][1], 0.0);
      const auto light = static_cast<float>(lighting.irradiance(Vec3::UnitZ(), p));
      const cv::Vec3f colour = albedo_row[x] * light + haze_row[x];
      row[x] = cv::Vec3b(cv::saturate_cast<uchar>(colour[0]), cv::saturate_cast<uchar>(colour[1]),
                         cv::saturate_cast<uchar>(colour[2]));
    }
  }
}

CourtRender CourtRenderer::render(const CourtScene& scene, std::uint64_t noise_seed) const {
  scene.validate();
  const cv::Size size(rays_.width(), rays_.height());
  CourtRender out;
  out.bgr.create(size, CV_8UC3);
  out.object_ids = cv::Mat(size, CV_32S, cv::Scalar(-1));
  light_floor(scene.lighting, out.bgr);

  const std::vector<SceneSphere> spheres = scene.spheres();
  const FloorBox robot{scene.robot.pose,
                       Vec2(scene.robot.length_m / 2.0, scene.robot.width_m / 2.0),
                       scene.robot.height_m};
  const int robot_index = static_cast<int>(spheres.size());
  std::vector<PixelBox> boxes;
  for (const SceneSphere& s : spheres) boxes.push_back(sphere_box(camera_, s, size));
  boxes.push_back(floor_box_box(camera_, robot, size));
  out.coverage.assign(boxes.size(), {});

  cv::Mat1b in_some_box(size, uchar{0});
  for (const PixelBox& b : boxes) {
    if (!b.empty()) in_some_box(cv::Rect(b.x0, b.y0, b.x1 - b.x0, b.y1 - b.y0)).setTo(1);
  }

  constexpr int n = kSamplesPerAxis;
  const Vec3& o = center_in_field_;
  std::vector<int> candidates;
  for (int y = 0; y < size.height; ++y) {
    const uchar* mask_row = in_some_box.ptr<uchar>(y);
    auto* row = out.bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < size.width; ++x) {
      if (!mask_row[x]) continue;
      candidates.clear();
      for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        if (boxes[static_cast<size_t>(i)].contains(x, y)) candidates.push_back(i);
      }
      const cv::Vec3f floor_colour(row[x][0], row[x][1], row[x][2]);
      cv::Vec3f sum(0.0f, 0.0f, 0.0f);
      for (int sy = 0; sy < n; ++sy) {
        for (int sx = 0; sx < n; ++sx) {
          const bool centre = 2 * sx + 1 == n && 2 * sy + 1 == n;
          const Vec3 d =
              centre ? rays_.at(x, y)
                     : rays_.interpolate(x + (sx + 0.5) / n - 0.5, y + (sy + 0.5) / n - 0.5);
          double best_t = std::numeric_limits<double>::infinity();
          int best = -1;
          Vec3 best_normal = Vec3::UnitZ();
          for (const int i : candidates) {
            std::optional<double> t;
            Vec3 normal;
            if (i == robot_index) {
              const std::optional<BoxHit> hit = intersect_floor_box(o, d, robot);
              if (hit) {
                t = hit->t;
                normal = hit->normal_in_field;
              }
            } else {
              const SceneSphere& s = spheres[static_cast<size_t>(i)];
              t = intersect_sphere(o, d, s.center_in_field, s.radius_m);
              if (t) normal = (o + *t * d - s.center_in_field) / s.radius_m;
            }
            if (!t) continue;
            ++out.coverage[static_cast<size_t>(i)].unoccluded_samples;
            if (*t < best_t) {
              best_t = *t;
              best = i;
              best_normal = normal;
            }
          }
          if (centre) out.object_ids.at<int>(y, x) = best;
          if (best < 0) {
            sum += floor_colour;
            continue;
          }
          ++out.coverage[static_cast<size_t>(best)].visible_samples;
          const cv::Vec3b& base =
              best == robot_index ? scene.robot.bgr : spheres[static_cast<size_t>(best)].bgr;
          sum += scaled(base, scene.lighting.irradiance(best_normal, o + best_t * d));
        }
      }
      sum *= 1.0f / (n * n);
      row[x] = cv::Vec3b(cv::saturate_cast<uchar>(sum[0]), cv::saturate_cast<uchar>(sum[1]),
                         cv::saturate_cast<uchar>(sum[2]));
    }
  }
  apply_image_effects(out.bgr, scene.effects, noise_seed);
  return out;
}

}  // namespace ballsight::sim
