#include "ballsight/sim/court_renderer.hpp"

#include "ballsight/core/error.hpp"
#include "ballsight/core/raycast_box.hpp"
#include "ballsight/sim/pixel_box.hpp"
#include "ballsight/sim/raycast.hpp"

namespace ballsight::sim {
namespace {

cv::Vec3f scaled(const cv::Vec3b& bgr, double k) {
  const auto f = static_cast<float>(k);
  return {bgr[0] * f, bgr[1] * f, bgr[2] * f};
}

double share(int part, int whole) {
  return whole > 0 ? static_cast<double>(part) / whole : 0.0;
}

}  // namespace

double ObjectCoverage::visible_fraction() const {
  return share(visible_samples, unoccluded_samples);
}

double ObjectCoverage::net_fraction() const {
  return share(net_samples, unoccluded_samples);
}

CourtRenderer::CourtRenderer(const CourtCamera& camera, const TennisCourtSpec& court)
    : camera_(camera),
      center_in_field_(camera.center_in_field()),
      rays_(camera.camera, camera.camera_from_field.rotation.transpose()),
      background_(camera, rays_, court, kSamplesPerAxis) {}

cv::Mat CourtRenderer::lit_background(const Lighting& lighting,
                                      const std::vector<FloorLeaf>& leaves) const {
  cv::Mat bgr(rays_.height(), rays_.width(), CV_8UC3);
  background_.light(lighting, leaves, bgr);
  return bgr;
}

CourtRender CourtRenderer::render(const CourtScene& scene, std::uint64_t noise_seed) const {
  scene.validate();
  return render(scene, noise_seed, lit_background(scene.lighting, scene.leaves));
}

CourtRender CourtRenderer::render(const CourtScene& scene, std::uint64_t noise_seed,
                                  const cv::Mat& lit_background) const {
  scene.validate();
  const cv::Size size(rays_.width(), rays_.height());
  require(lit_background.type() == CV_8UC3 && lit_background.size() == size, "lit background",
          "must be the camera's image size, CV_8UC3 (CourtRenderer::lit_background)");
  CourtRender out;
  lit_background.copyTo(out.bgr);
  out.object_ids = cv::Mat(size, CV_32S, cv::Scalar(-1));

  const std::vector<SceneSphere> spheres = scene.spheres();
  const FloorBox robot{scene.robot.pose,
                       Vec2(scene.robot.length_m / 2.0, scene.robot.width_m / 2.0),
                       scene.robot.height_m};
  const int robot_index = static_cast<int>(spheres.size());
  std::vector<PixelBox> boxes;
  for (const SceneSphere& s : spheres) boxes.push_back(sphere_pixel_box(camera_, s, size));
  boxes.push_back(floor_box_pixel_box(camera_, robot, size));
  for (const FloorBottle& b : scene.bottles)
    boxes.push_back(floor_box_pixel_box(camera_, b.bounds(), size));
  const int first_obstacle = static_cast<int>(boxes.size());
  for (const CourtObstacle& b : scene.obstacles)
    boxes.push_back(floor_box_pixel_box(camera_, b.bounds(), size));
  out.coverage.assign(boxes.size(), {});

  const Vec3& o = center_in_field_;
  const auto bottle = [&](int i) -> const FloorBottle& {
    return scene.bottles[static_cast<size_t>(i - robot_index - 1)];
  };
  const auto obstacle = [&](int i) -> const CourtObstacle& {
    return scene.obstacles[static_cast<size_t>(i - first_obstacle)];
  };
  // Object i: a sphere, the robot, a bottle or an obstacle (in the order of `boxes`).
  const auto hit = [&](int i, const Vec3& d) -> std::optional<BoxHit> {
    if (i == robot_index) return intersect_floor_box(o, d, robot);
    if (i >= first_obstacle) return obstacle(i).intersect(o, d);
    if (i > robot_index) return bottle(i).intersect(o, d);
    const SceneSphere& s = spheres[static_cast<size_t>(i)];
    const std::optional<double> t = intersect_sphere(o, d, s.center_in_field, s.radius_m);
    if (!t) return std::nullopt;
    return BoxHit{*t, (o + *t * d - s.center_in_field) / s.radius_m};
  };
  const auto albedo = [&](int i) -> const cv::Vec3b& {
    if (i == robot_index) return scene.robot.bgr;
    if (i >= first_obstacle) return obstacle(i).bgr;
    if (i > robot_index) return bottle(i).bgr;
    return spheres[static_cast<size_t>(i)].bgr;
  };

  cv::Mat1b in_some_box(size, uchar{0});
  for (const PixelBox& b : boxes) {
    if (!b.empty()) in_some_box(cv::Rect(b.x0, b.y0, b.x1 - b.x0, b.y1 - b.y0)).setTo(1);
  }

  constexpr int n = kSamplesPerAxis;
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
      // Samples where no object is the nearest surface show the background (floor or net).
      const cv::Vec3f background(row[x][0], row[x][1], row[x][2]);
      cv::Vec3f sum(0.0f, 0.0f, 0.0f);
      for (int sy = 0; sy < n; ++sy) {
        for (int sx = 0; sx < n; ++sx) {
          const Vec3 d = rays_.sample(x, y, sx, sy, n);
          const double net_t = background_.net_distance(d);
          double best_t = net_t;
          int best = -1;
          Vec3 best_normal = Vec3::UnitZ();
          for (const int i : candidates) {
            const std::optional<BoxHit> h = hit(i, d);
            if (!h) continue;
            ObjectCoverage& coverage = out.coverage[static_cast<size_t>(i)];
            ++coverage.unoccluded_samples;
            if (h->t > net_t) ++coverage.net_samples;
            if (h->t < best_t) {
              best_t = h->t;
              best = i;
              best_normal = h->normal_in_field;
            }
          }
          if (2 * sx + 1 == n && 2 * sy + 1 == n) out.object_ids.at<int>(y, x) = best;
          if (best < 0) {
            sum += background;
            continue;
          }
          ++out.coverage[static_cast<size_t>(best)].visible_samples;
          sum += scaled(albedo(best), scene.lighting.irradiance(best_normal, o + best_t * d));
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
