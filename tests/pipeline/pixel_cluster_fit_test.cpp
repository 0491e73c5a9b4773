// The k-ball pixel fit (world/pixel_cluster_fit.hpp) on rendered clusters: the corner cameras'
// images of touching balls, a pixel or so across, through the court detector and the world model.

#include "ballsight/world/pixel_cluster_fit.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "ballsight/detect/court_detector.hpp"
#include "ballsight/world/court_world.hpp"
#include "detect/court_scene_support.hpp"
#include "field_cameras.hpp"

namespace ballsight {
namespace {

constexpr double kRadius = 0.0335;

// Each corner camera's detections of anti-aliased balls at `balls` (centres on the field).
std::vector<std::optional<std::vector<PixelDetection>>> detect_balls(
    const std::vector<FieldCamera>& cameras, const std::vector<Vec2>& balls) {
  std::vector<std::optional<std::vector<PixelDetection>>> out;
  for (size_t c = 0; c < cameras.size(); ++c) {
    std::vector<test::Disc> discs;
    for (const Vec2& b : balls) {
      const Vec3 center(b.x(), b.y(), kRadius);
      const double range = (center - cameras[c].center_in_field()).norm();
      discs.push_back(
          {*cameras[c].pixel_from_field(center), 800.0 * kRadius / range, test::kBallYellow});
    }
    const cv::Mat image = test::draw_discs(discs, 1.0, c + 1, {1280, 720});
    CourtDetector detector(cameras[c]);
    out.emplace_back(detector.detect(image));
  }
  return out;
}

// The largest distance from a true ball to the nearest estimate.
double worst_error(const std::vector<Vec2>& truth, const std::vector<FusedBall>& estimates) {
  double worst = 0.0;
  for (const Vec2& t : truth) {
    double nearest = 1e9;
    for (const FusedBall& e : estimates) nearest = std::min(nearest, (e.position_m - t).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

struct Cluster {
  const char* name;
  std::vector<Vec2> balls;
};

// Touching balls 1-1.6 px in radius merge into one blob per camera. Without the pixel fit the
// world model ends with a ball too few or too many in three of these five clusters (four before
// the court detector took its evidence across the floor's chroma); with it, every cluster has its
// count and every ball is found within 1 cm.
TEST(PixelClusterFit, FindsTheBallsOfMergedClusters) {
  const double d = 2.0 * kRadius;
  const auto at = [](const Vec2& where, const std::vector<Vec2>& shape) {
    std::vector<Vec2> balls;
    for (const Vec2& p : shape) balls.push_back(where + p);
    return balls;
  };
  const Vec2 far(-11.0, 3.3);  // 1.0-1.3 px radius in the four views
  const std::vector<Cluster> clusters{
      {"row of three", at({5.0, 3.0}, {{0, 0}, {d, 0}, {2 * d, 0}})},
      {"square of four", at({5.0, 3.0}, {{0, 0}, {d, 0}, {0, d}, {d, d}})},
      {"diamond of four", at(far, {{0, 0}, {d, 0}, {0.5 * d, 0.866 * d}, {0.5 * d, -0.866 * d}})},
      {"rhombus of four", at(far, {{0, 0}, {d, 0}, {0.5 * d, 0.866 * d}, {1.5 * d, 0.866 * d}})},
      {"T of four", at(far, {{0, 0}, {d, 0}, {2 * d, 0}, {d, 0.9 * d}})}};
  const std::vector<FieldCamera> cameras = test::corner_cameras();
  int old_wrong = 0;
  for (const Cluster& cluster : clusters) {
    SCOPED_TRACE(cluster.name);
    const auto detections = detect_balls(cameras, cluster.balls);
    CourtWorldOptions without;
    without.pixel_fit.enabled = false;
    const WorldModel old_model = build_world_model(cameras, detections, without);
    old_wrong += old_model.balls.size() != cluster.balls.size();
    const WorldModel model = build_world_model(cameras, detections, {});
    ASSERT_EQ(model.balls.size(), cluster.balls.size());
    EXPECT_LT(worst_error(cluster.balls, model.balls), 0.01);
  }
  EXPECT_GE(old_wrong, 3);  // the path without the fit miscounts three of the five
}

// A lone ball seen split by one camera is not made two: the fit needs no further ball.
TEST(PixelClusterFit, ALoneBallStaysOne) {
  const std::vector<FieldCamera> cameras = test::corner_cameras();
  const std::vector<Vec2> truth{{2.0, 1.0}};
  const WorldModel model = build_world_model(cameras, detect_balls(cameras, truth), {});
  ASSERT_EQ(model.balls.size(), 1u);
  EXPECT_LT(worst_error(truth, model.balls), 0.01);
}

TEST(PixelClusterFit, InvalidOptionsAreNamed) {
  PixelFitOptions options;
  options.ball_penalty = 0.0;
  EXPECT_THROW(options.validate(), InputError);
}

}  // namespace
}  // namespace ballsight
