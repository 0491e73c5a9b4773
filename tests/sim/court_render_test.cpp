#include <gtest/gtest.h>

#include <map>
#include <opencv2/imgproc.hpp>

#include "ballsight/sim/court_renderer.hpp"
#include "ballsight/sim/court_scenario.hpp"
#include "ballsight/sim/silhouette.hpp"
#include "polygon_area.hpp"
#include "sim/court_test_support.hpp"

namespace ballsight::sim {
namespace {

using test_support::polygon_area;

using test_support::clean_scenario;
using test_support::render_in_all_cameras;
using test_support::shared_court;

struct HsvRange {
  cv::Scalar lo, hi;
};

/// Colour classes a detector would use (OpenCV HSV: H in [0, 180)).
HsvRange hsv_range(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::tennis_ball:
      return {{25, 100, 60}, {45, 255, 255}};
    case ObjectKind::reference_ball:
      return {{2, 120, 60}, {18, 255, 255}};
    case ObjectKind::robot_front_marker:
      return {{150, 80, 60}, {175, 255, 255}};
    case ObjectKind::robot_back_marker:
      return {{105, 150, 60}, {125, 255, 255}};
  }
  return {};
}

struct Blob {
  Vec2 centroid;
  int area = 0;
};

/// The connected component of the colour class containing `pixel`, segmented with cv::inRange.
std::optional<Blob> blob_at(const cv::Mat& bgr, const HsvRange& range, const Vec2& pixel) {
  cv::Mat hsv, mask, labels, stats, centroids;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  cv::inRange(hsv, range.lo, range.hi, mask);
  cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  const int x = static_cast<int>(std::lround(pixel.x())),
            y = static_cast<int>(std::lround(pixel.y()));
  if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) return std::nullopt;
  const int label = labels.at<int>(y, x);
  if (label == 0) return std::nullopt;
  return Blob{{centroids.at<double>(label, 0), centroids.at<double>(label, 1)},
              stats.at<int>(label, cv::CC_STAT_AREA)};
}

/// True when no other object than `index` (and `allowed`, if any) is seen within `margin_px` of
/// the object's outline: its blob can only be its own.
bool isolated(const CourtRender& render, int index, int allowed, const std::vector<Vec2>& outline,
              int margin_px) {
  Eigen::AlignedBox2d box;
  for (const Vec2& p : outline) box.extend(p);
  const int x0 = static_cast<int>(std::floor(box.min().x())) - margin_px;
  const int y0 = static_cast<int>(std::floor(box.min().y())) - margin_px;
  const int x1 = static_cast<int>(std::ceil(box.max().x())) + margin_px;
  const int y1 = static_cast<int>(std::ceil(box.max().y())) + margin_px;
  if (x0 < 0 || y0 < 0 || x1 >= render.object_ids.cols || y1 >= render.object_ids.rows) {
    return false;
  }
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const int id = render.object_ids.at<int>(y, x);
      if (id != -1 && id != index && id != allowed) return false;
    }
  }
  return true;
}

/// Below this silhouette area (a radius of 1.6 px) a blob is a handful of mixed pixels and its
/// centroid depends on the colour thresholds more than on the renderer.
constexpr double kMinBlobAreaPx = 8.0;

struct CentroidStats {
  std::map<ObjectKind, int> checked;
  Vec2 offset_sum = Vec2::Zero();  // signed: a bias does not average out
  double worst = 0.0;
  int total() const {
    int n = 0;
    for (const auto& [kind, count] : checked) n += count;
    return n;
  }
};

/// Compares the blob centroid of every isolated, fully visible, large enough object with its
/// analytic silhouette centroid in clean renders of scenario scenes; `flat` lights everything
/// evenly (no shading gradient across a ball).
CentroidStats check_blob_centroids(bool flat) {
  CentroidStats stats;
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    SCOPED_TRACE("scene seed " + std::to_string(seed) + (flat ? ", flat light" : ""));
    auto scene = make_court_scene(TennisCourtSpec{}, clean_scenario(), seed);
    if (flat) scene.lighting.ambient = 1.0;
    const auto rendered = render_in_all_cameras(scene);
    const int robot_box = static_cast<int>(rendered.truth.size());
    for (size_t c = 0; c < rendered.renders.size(); ++c) {
      const CourtCamera& camera = shared_court().rig.cameras[c];
      for (size_t i = 0; i < rendered.truth.size(); ++i) {
        const SphereTruth& t = rendered.truth[i];
        const SphereViewTruth& view = t.views[c];
        if (!view.visible || view.visible_fraction < 1.0) continue;
        const auto outline = sphere_outline_pixels(
            camera.camera, camera.camera_from_field * t.sphere.center_in_field, t.sphere.radius_m,
            96);
        EXPECT_TRUE(outline && view.silhouette_centroid_px);
        if (!outline || polygon_area(*outline) < kMinBlobAreaPx) continue;
        // The markers sit on the robot box: grey, in no colour class.
        const bool marker = t.sphere.kind == ObjectKind::robot_front_marker ||
                            t.sphere.kind == ObjectKind::robot_back_marker;
        if (!isolated(rendered.renders[c], static_cast<int>(i), marker ? robot_box : -1, *outline,
                      3)) {
          continue;
        }
        const auto blob = blob_at(rendered.renders[c].bgr, hsv_range(t.sphere.kind),
                                  *view.silhouette_centroid_px);
        const std::string what = std::string(object_kind_name(t.sphere.kind)) + " " +
                                 std::to_string(t.sphere.id) + " camera " + std::to_string(c);
        EXPECT_TRUE(blob) << what << " at " << view.silhouette_centroid_px->transpose();
        if (!blob) continue;
        EXPECT_LT((blob->centroid - *view.silhouette_centroid_px).norm(), 0.5)
            << what << ", blob area " << blob->area;
        ++stats.checked[t.sphere.kind];
        stats.offset_sum += blob->centroid - *view.silhouette_centroid_px;
        stats.worst = std::max(stats.worst, (blob->centroid - *view.silhouette_centroid_px).norm());
      }
    }
  }
  EXPECT_GE(stats.checked[ObjectKind::tennis_ball], 60);
  EXPECT_GE(stats.checked[ObjectKind::reference_ball], 8);
  EXPECT_GE(stats.checked[ObjectKind::robot_front_marker], 6);
  EXPECT_GE(stats.checked[ObjectKind::robot_back_marker], 6);
  return stats;
}

TEST(CourtRender, BlobCentroidsMatchTheAnalyticSilhouette) {
  // Sunlit balls are darker underneath, so their colour blobs sit slightly high: within 0.5 px.
  const CentroidStats stats = check_blob_centroids(false);
  std::cout << stats.total() << " blobs, worst " << stats.worst << " px, mean offset "
            << (stats.offset_sum / stats.total()).transpose() << " px\n";
}

TEST(CourtRender, EvenlyLitBlobCentroidsAreUnbiased) {
  const CentroidStats stats = check_blob_centroids(true);
  const Vec2 mean_offset = stats.offset_sum / stats.total();
  EXPECT_LT(mean_offset.norm(), 0.03) << mean_offset.transpose() << " over " << stats.total();
  std::cout << stats.total() << " blobs, worst " << stats.worst << " px, mean offset "
            << mean_offset.transpose() << " px\n";
}

}  // namespace
}  // namespace ballsight::sim
