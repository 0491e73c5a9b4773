#include "ballsight/sim/court_background.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "ballsight/sim/pixel_box.hpp"

namespace ballsight::sim {
namespace {

const cv::Vec3f kSkyZenithBgr{215.0f, 160.0f, 110.0f};
constexpr double kHazeDistanceM = 400.0;
constexpr double kMaxAlongFootprintM = 20.0;

cv::Vec3f to_float(const cv::Vec3b& c) {
  return {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
}

cv::Vec3b to_bgr8(const cv::Vec3f& c) {
  return {cv::saturate_cast<uchar>(c[0]), cv::saturate_cast<uchar>(c[1]),
          cv::saturate_cast<uchar>(c[2])};
}

cv::Vec3f lit_floor(const Lighting& lighting, const cv::Vec3f& albedo, const cv::Vec3f& haze,
                    const cv::Vec2f& point) {
  const Vec3 p(point[0], point[1], 0.0);
  return albedo * static_cast<float>(lighting.irradiance(Vec3::UnitZ(), p)) + haze;
}

}  // namespace

float haze_share(double t_m) {
  return static_cast<float>(1.0 - std::exp(-t_m / kHazeDistanceM));
}

CourtBackground::CourtBackground(const CourtCamera& camera, const RayTable& rays,
                                 const TennisCourtSpec& court, int samples_per_axis)
    : center_in_field_(camera.center_in_field()), net_(TennisNet::of(court)) {
  court.validate();
  precompute_floor(rays, court);
  precompute_net(camera, rays, samples_per_axis);
}

void CourtBackground::precompute_floor(const RayTable& rays, const TennisCourtSpec& court) {
  const cv::Size size(rays.width(), rays.height());
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
      const Vec3 d = rays.at(x, y);
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
      const Vec3 next = rays.at(x + 1 < size.width ? x + 1 : x - 1, y);
      const double across = t * (next - d).norm();
      const double along = std::min(across / -d.z(), kMaxAlongFootprintM);
      const Vec2 u = d.head<2>().normalized();
      const Vec2 half(0.5 * (along * std::abs(u.x()) + across * std::abs(u.y())),
                      0.5 * (along * std::abs(u.y()) + across * std::abs(u.x())));
      const float haze = haze_share(t);
      albedo_row[x] = floor_albedo(court, lines, p.head<2>(), half) * (1.0f - haze);
      haze_row[x] = kSkyHorizonBgr * haze;
      point_row[x] = cv::Vec2f(static_cast<float>(p.x()), static_cast<float>(p.y()));
    }
  }
}

void CourtBackground::precompute_net(const CourtCamera& camera, const RayTable& rays,
                                     int samples_per_axis) {
  if (!net_) return;
  const int n = samples_per_axis;
  const float weight = 1.0f / static_cast<float>(n * n);
  const PixelBox box =
      floor_box_pixel_box(camera, net_->bounds(), cv::Size(rays.width(), rays.height()));
  const Vec3& o = center_in_field_;
  for (int y = box.y0; y < box.y1; ++y) {
    for (int x = box.x0; x < box.x1; ++x) {
      NetPixel pixel{x, y, 1.0f, {}, {}, Vec3::Zero(), Vec3::Zero()};
      int hits = 0;
      for (int sy = 0; sy < n; ++sy) {
        for (int sx = 0; sx < n; ++sx) {
          const Vec3 d = rays.sample(x, y, sx, sy, n);
          const std::optional<NetHit> hit = net_->intersect(o, d);
          if (!hit) continue;
          ++hits;
          const float haze = haze_share(hit->t);
          pixel.albedo += to_float(net_->albedo(hit->part)) * ((1.0f - haze) * weight);
          pixel.haze += kSkyHorizonBgr * (haze * weight);
          pixel.normal_in_field += hit->normal_in_field;
          pixel.point_in_field += o + hit->t * d;
        }
      }
      if (hits == 0) continue;
      pixel.floor_share = 1.0f - static_cast<float>(hits) * weight;
      assert(pixel.normal_in_field.norm() > 0.0);  // every normal faces the camera
      pixel.normal_in_field.normalize();
      pixel.point_in_field /= hits;
      net_pixels_.push_back(pixel);
    }
  }
}

void CourtBackground::light(const Lighting& lighting, const std::vector<FloorLeaf>& leaves,
                            cv::Mat& bgr) const {
  // The leaves' bounding box on the floor: most pixels need no test against each leaf.
  Eigen::AlignedBox2d litter;
  for (const FloorLeaf& leaf : leaves) {
    litter.extend(leaf.center_in_field - Vec2::Constant(leaf.half_length_m));
    litter.extend(leaf.center_in_field + Vec2::Constant(leaf.half_length_m));
  }
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* albedo_row = floor_albedo_.ptr<cv::Vec3f>(y);
    const auto* haze_row = floor_haze_.ptr<cv::Vec3f>(y);
    const auto* point_row = floor_point_.ptr<cv::Vec2f>(y);
    auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      cv::Vec3f albedo = albedo_row[x];
      const Vec2 p(point_row[x][0], point_row[x][1]);
      if (!leaves.empty() && albedo != cv::Vec3f() && litter.contains(p)) {
        for (const FloorLeaf& leaf : leaves)
          if (leaf.covers(p))
            albedo = to_float(leaf.bgr) * (1.0f - haze_row[x][0] / kSkyHorizonBgr[0]);
      }
      row[x] = to_bgr8(lit_floor(lighting, albedo, haze_row[x], point_row[x]));
    }
  }
  for (const NetPixel& p : net_pixels_) {
    const cv::Vec3f floor =
        lit_floor(lighting, floor_albedo_.at<cv::Vec3f>(p.y, p.x),
                  floor_haze_.at<cv::Vec3f>(p.y, p.x), floor_point_.at<cv::Vec2f>(p.y, p.x));
    const auto light = static_cast<float>(lighting.irradiance(p.normal_in_field, p.point_in_field));
    bgr.at<cv::Vec3b>(p.y, p.x) = to_bgr8(floor * p.floor_share + p.albedo * light + p.haze);
  }
}

double CourtBackground::net_distance(const Vec3& direction) const {
  if (!net_) return std::numeric_limits<double>::infinity();
  const std::optional<NetHit> hit = net_->intersect(center_in_field_, direction);
  return hit ? hit->t : std::numeric_limits<double>::infinity();
}

}  // namespace ballsight::sim
